// Surfaces for scene.frag (prepended to it): the procedural patterns of generated materials and the
// metallic-roughness reflectance. Patterns work in the metric coordinates of the part's own mesh
// (v_p_M) and are box-filtered over the pixel's footprint (fwidth), so that a facade 2 km away shows
// its mean colour instead of aliased windows. Every random choice hashes the instance id and a cell,
// so a building keeps its lit windows from frame to frame and from run to run.
precision highp float;
precision highp int;

// The pattern ids of engine::SurfacePattern.
const uint kPatternFacade = 1u;
const uint kPatternRoof = 2u;
const uint kPatternAsphalt = 3u;
const uint kPatternSidewalk = 4u;
const uint kPatternGrass = 5u;
const uint kPatternSoil = 6u;
const uint kPatternRock = 7u;
const uint kPatternBark = 8u;
const uint kPatternFoliage = 9u;
const uint kPatternCarPaint = 10u;  // shading only (scene.frag): a clear coat

// What a pattern makes of a point of the surface.
struct Surface {
  vec3 albedo;      // linear base colour
  float roughness;  // perceptual, [0.02, 1]
  float metallic;
};

// A 32-bit integer hash of a cell and a seed (xorshift-multiply rounds; any good avalanche does).
uint HashCell(ivec2 cell, uint seed) {
  uint h = uint(cell.x) * 0x9E3779B1u ^ (uint(cell.y) * 0x85EBCA77u + seed * 0xC2B2AE3Du);
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return h;
}

// Uniform on [0, 1) from HashCell.
float Random01(ivec2 cell, uint seed) {
  return float(HashCell(cell, seed) >> 8) * (1.0 / 16777216.0);
}

// Value noise on [0, 1): random values at integer points, smoothly (C1) interpolated.
float ValueNoise(vec2 p, uint seed) {
  vec2 i = floor(p);
  vec2 f = p - i;
  vec2 u = f * f * (3.0 - 2.0 * f);
  ivec2 c = ivec2(i);
  float a = Random01(c, seed);
  float b = Random01(c + ivec2(1, 0), seed);
  float d = Random01(c + ivec2(0, 1), seed);
  float e = Random01(c + ivec2(1, 1), seed);
  return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

// Noise whose contrast fades to its mean (0.5) once a period covers fewer than about two pixels
// (`footprint`: the pixel's size in units of the noise's period).
float FilteredNoise(vec2 p, uint seed, float footprint) {
  return mix(ValueNoise(p, seed), 0.5, smoothstep(0.25, 0.6, footprint));
}

// The integral over [0, x] of a pulse train of period 1 that is 1 on [0, duty) of each period.
float PulseIntegral(float x, float duty) {
  return floor(x) * duty + min(fract(x), duty);
}

// The share of a pixel of footprint `w` (in periods) centred at `x` that falls on the pulses
// [0, duty) of each period: the pulse train box-filtered exactly, so that it tends to `duty`
// when a period shrinks under a pixel.
float PulseTrain(float x, float duty, float w) {
  w = max(w, 1e-4);
  return (PulseIntegral(x + 0.5 * w, duty) - PulseIntegral(x - 0.5 * w, duty)) / w;
}

// The share of a pixel of footprint `w` centred at `x` inside [lo, hi] (one pulse, box-filtered).
float Band(float x, float lo, float hi, float w) {
  w = max(w, 1e-4);
  return max(min(x + 0.5 * w, hi) - max(x - 0.5 * w, lo), 0.0) / w;
}

// Walls of a unit box: storeys of `storey_m` with windows at a pitch near `pitch_m` (a whole number
// of them across each face, centred), a taller shop front on the ground floor, window frames,
// floor slabs, and no windows in the parapet above the last whole storey.
void Facade(inout Surface s, vec3 p, vec3 n, vec3 size, vec2 pattern_m, uint seed) {
  if (abs(n.z) > 0.5) return;  // the box's top and bottom
  bool faces_y = abs(n.y) > abs(n.x);
  float u = faces_y ? p.x : p.y;
  float width = faces_y ? size.x : size.y;
  float height = 0.5 * size.z - p.z;  // up from the base (z is down)
  float storey_m = pattern_m.x;
  float columns = max(1.0, floor(width / pattern_m.y + 0.5));
  vec2 q = vec2((u + 0.5 * width) * columns / width, height / storey_m);
  vec2 w = fwidth(q);
  float storeys = floor(size.z / storey_m);
  bool ground = q.y < 1.0;
  vec2 lo = ground ? vec2(0.08, 0.05) : vec2(0.22, 0.32);
  vec2 hi = ground ? vec2(0.92, 0.80) : vec2(0.78, 0.86);
  float in_storeys = Band(q.y, 0.0, storeys, w.y);
  float glass = PulseTrain(q.x - lo.x, hi.x - lo.x, w.x) *
                PulseTrain(q.y - lo.y, hi.y - lo.y, w.y) * in_storeys;
  const float kFrame = 0.05;
  float framed = PulseTrain(q.x - lo.x + kFrame, hi.x - lo.x + 2.0 * kFrame, w.x) *
                 PulseTrain(q.y - lo.y + kFrame, hi.y - lo.y + 2.0 * kFrame, w.y) * in_storeys;
  float slab = PulseTrain(q.y + 0.02, 0.04, w.y) * in_storeys;
  // Weathering: a faint large-scale variation of the wall.
  float grime = FilteredNoise(vec2(u, height) * 0.25, seed, 0.25 * max(w.x * width / columns, 1e-4));
  vec3 wall = s.albedo * (0.9 + 0.2 * grime) * (1.0 - 0.25 * slab);
  // Panes: mostly dark glass; some lit from inside, some with pale blinds (per window and building).
  ivec2 cell = ivec2(floor(q));
  float pick = Random01(cell, seed);
  vec3 pane = pick < 0.12   ? vec3(0.55, 0.45, 0.30)
              : pick < 0.30 ? vec3(0.30, 0.30, 0.28)
                            : vec3(0.025, 0.03, 0.035);
  // Far away the pick flickers from pixel to pixel: use the mean pane.
  pane = mix(pane, vec3(0.10, 0.095, 0.085), smoothstep(0.25, 0.6, max(w.x, w.y)));
  vec3 frame_colour = vec3(0.55, 0.55, 0.53);
  s.albedo = mix(mix(wall, frame_colour, framed - glass), pane, glass);
  s.roughness = mix(s.roughness, 0.06, glass);
}

// Roofing: rows of tiles `pattern_m.x` deep on a slope (a shaded lap at each row's lower edge),
// gravel of grain `pattern_m.y` on a flat roof.
void Roof(inout Surface s, vec3 p, vec3 n, vec2 pattern_m, uint seed) {
  float slope_cos = abs(n.z);
  if (slope_cos > 0.97) {
    vec2 g = p.xy / pattern_m.y;
    s.albedo *= 0.8 + 0.4 * FilteredNoise(g, seed, max(fwidth(g.x), fwidth(g.y)));
    return;
  }
  float sin_slope = sqrt(max(1.0 - slope_cos * slope_cos, 1e-4));
  float row = -p.z / (pattern_m.x * sin_slope);
  float w = fwidth(row);
  float lap = PulseTrain(row, 0.15, w);
  float tile = FilteredNoise(vec2(dot(p.xy, vec2(-n.y, n.x)) / (0.8 * pattern_m.x), row), seed, w);
  s.albedo *= (1.0 - 0.35 * lap) * (0.85 + 0.3 * tile);
}

// A road slab (a box longer than wide): asphalt grain, solid edge lines, a dashed centre line on
// roads at least two lanes (`pattern_m.x`) wide, dashes one third of `pattern_m.y`, and zebra
// crossings across the road near both ends of the slab.
void Asphalt(inout Surface s, vec3 p, vec3 size, vec2 pattern_m, uint seed) {
  bool along_x = size.x >= size.y;
  float u = along_x ? p.x : p.y;
  float v = along_x ? p.y : p.x;
  float len = along_x ? size.x : size.y;
  float half_width = 0.5 * (along_x ? size.y : size.x);
  float wu = fwidth(u);
  float wv = fwidth(v);
  float paint = 0.0;
  if (half_width >= pattern_m.x) {
    paint = Band(v, -0.075, 0.075, wv) * PulseTrain(u / pattern_m.y, 1.0 / 3.0, wu / pattern_m.y);
  }
  paint = max(paint, Band(abs(v), half_width - 0.45, half_width - 0.3, wv));
  float to_end = 0.5 * len - abs(u);
  float zebra = Band(to_end, 1.0, 4.0, wu) * Band(abs(v), 0.0, half_width - 0.6, wv) *
                PulseTrain(v / 1.0 + 0.25, 0.5, wv);
  paint = max(paint, zebra);
  vec2 g = p.xy / 0.3;
  float grain = FilteredNoise(g, seed, max(fwidth(g.x), fwidth(g.y)));
  float wear = FilteredNoise(p.xy / 6.0, seed + 1u, max(wu, wv) / 6.0);
  s.albedo = mix(s.albedo * (0.8 + 0.25 * grain + 0.15 * wear), vec3(0.75, 0.75, 0.72), paint);
  s.roughness = mix(s.roughness, 0.55, paint);
}

// Paving slabs of `pattern_m` with dark joints, each slab a little lighter or darker.
void Sidewalk(inout Surface s, vec3 p, vec2 pattern_m, uint seed) {
  vec2 q = p.xy / pattern_m;
  vec2 w = fwidth(q);
  float joint = max(PulseTrain(q.x, 0.015 / pattern_m.x, w.x), PulseTrain(q.y, 0.015 / pattern_m.y, w.y));
  float shade = mix(Random01(ivec2(floor(q)), seed), 0.5, smoothstep(0.25, 0.6, max(w.x, w.y)));
  s.albedo *= (0.9 + 0.2 * shade) * (1.0 - 0.4 * joint);
}

// Ground cover: a large variation of size pattern_m.x between the base colour and `other`, and a
// grain of size pattern_m.y.
void Ground(inout Surface s, vec3 p, vec2 pattern_m, vec3 other, uint seed) {
  vec2 big = p.xy / pattern_m.x;
  vec2 small = p.xy / pattern_m.y;
  float wb = max(fwidth(big.x), fwidth(big.y));
  float ws = max(fwidth(small.x), fwidth(small.y));
  float patches = FilteredNoise(big, seed, wb) * 0.65 + FilteredNoise(big * 3.7, seed + 1u, wb * 3.7) * 0.35;
  float grain = FilteredNoise(small, seed + 2u, ws);
  s.albedo = mix(s.albedo, other, smoothstep(0.45, 0.8, patches)) * (0.8 + 0.4 * grain);
}

// Rock: strata every pattern_m.x (in height), broken along them, and a grain of pattern_m.y.
void Rock(inout Surface s, vec3 p, vec2 pattern_m, uint seed) {
  float layer = (-p.z + 0.6 * pattern_m.x * ValueNoise(p.xy / (4.0 * pattern_m.x), seed)) / pattern_m.x;
  float wl = fwidth(layer);
  float strata = FilteredNoise(vec2(layer, 0.5), seed + 1u, wl);
  vec2 g = p.xy / pattern_m.y;
  float grain = FilteredNoise(g + vec2(p.z / pattern_m.y, 0.0), seed + 2u, max(fwidth(g.x), fwidth(g.y)));
  s.albedo *= (0.75 + 0.35 * strata) * (0.85 + 0.3 * grain);
}

// A trunk (a cylinder about z): furrows every pattern_m.x round it, pattern_m.y long.
void Bark(inout Surface s, vec3 p, vec3 size, vec2 pattern_m, uint seed) {
  float around = atan(p.y, p.x) * 0.25 * (size.x + size.y);  // arc length on the mean radius
  vec2 q = vec2(around / pattern_m.x, p.z / pattern_m.y);
  float furrow = FilteredNoise(q, seed, max(fwidth(q.x), fwidth(q.y)));
  s.albedo *= 0.55 + 0.75 * furrow * furrow;
}

// A crown: clumps of leaves (pattern_m.x) with shade between them, a leaf-sized grain
// (pattern_m.y), and darker toward the crown's underside.
void Foliage(inout Surface s, vec3 p, vec3 size, vec2 pattern_m, uint seed) {
  vec2 c = vec2(p.x + 0.6 * p.z, p.y - 0.4 * p.z) / pattern_m.x;
  vec2 l = vec2(p.x - 0.3 * p.z, p.y + 0.7 * p.z) / pattern_m.y;
  float clumps = FilteredNoise(c, seed, max(fwidth(c.x), fwidth(c.y)));
  float leaves = FilteredNoise(l, seed + 1u, max(fwidth(l.x), fwidth(l.y)));
  float below = clamp(0.5 + p.z / max(size.z, 1e-3), 0.0, 1.0);  // 0 at the top, 1 at the bottom
  s.albedo *= (0.45 + 0.8 * clumps) * (0.8 + 0.4 * leaves) * mix(1.1, 0.7, below);
}

// The pattern `id` applied to the base surface at mesh point p (normal n), for the part of scale
// `size` of instance `instance`.
Surface ApplyPattern(Surface s, uint id, vec3 p, vec3 n, vec3 size, vec2 pattern_m, uint instance) {
  uint seed = instance * 0x27D4EB2Fu + id;
  if (id == kPatternFacade) Facade(s, p, n, size, pattern_m, seed);
  else if (id == kPatternRoof) Roof(s, p, n, pattern_m, seed);
  else if (id == kPatternAsphalt) Asphalt(s, p, size, pattern_m, seed);
  else if (id == kPatternSidewalk) Sidewalk(s, p, pattern_m, seed);
  else if (id == kPatternGrass) Ground(s, p, pattern_m, vec3(0.36, 0.34, 0.16), seed);
  else if (id == kPatternSoil) Ground(s, p, pattern_m, vec3(0.26, 0.19, 0.12), seed);
  else if (id == kPatternRock) Rock(s, p, pattern_m, seed);
  else if (id == kPatternBark) Bark(s, p, size, pattern_m, seed);
  else if (id == kPatternFoliage) Foliage(s, p, size, pattern_m, seed);
  s.albedo = clamp(s.albedo, 0.0, 1.0);
  return s;
}

// Pi times the specular reflectance toward the viewer of light from `l` (n, v, l unit vectors,
// cosines clamped): the Cook-Torrance microfacet BRDF times cos(theta_l), with the GGX
// (Trowbridge-Reitz) distribution D = a^2 / (pi (cos^2 theta_h (a^2 - 1) + 1)^2), a = roughness^2
// (Burley 2012); Smith's height-correlated visibility term in Hammon's approximation without square
// roots, V = 0.5 / mix(2 n.l n.v, n.l + n.v, a) ("PBR Diffuse Lighting for GGX+Smith
// Microsurfaces", GDC 2017; Heitz 2014, eq. 99 is the exact form); Schlick's Fresnel
// F = F0 + (1 - F0)(1 - v.h)^5. The pi cancels D's, as the diffuse term leaves out its 1 / pi.
vec3 SpecularSun(vec3 n, vec3 v, vec3 l, float roughness, vec3 f0) {
  vec3 h = normalize(v + l);
  float nl = max(dot(n, l), 0.0);
  float nv = max(dot(n, v), 1e-4);
  float nh = max(dot(n, h), 0.0);
  float a = roughness * roughness;
  float a2 = a * a;
  float d = nh * nh * (a2 - 1.0) + 1.0;
  float V = 0.5 / (mix(2.0 * nl * nv, nl + nv, a) + 1e-6);
  float m = 1.0 - max(dot(v, h), 0.0);
  float m2 = m * m;
  vec3 F = f0 + (1.0 - f0) * (m2 * m2 * m);
  return (a2 / (d * d)) * V * nl * F;
}

// The directional albedo of the same BRDF under uniform light (the scale and bias of F0 integrated
// over the hemisphere): Karis's analytic fit for mobile ("Physically Based Shading on Mobile", 2014),
// used for the sky's specular light.
vec3 EnvironmentReflectance(float nv, float roughness, vec3 f0) {
  vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r.x * r.x, exp2(-9.28 * nv)) * r.x + r.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
  return f0 * ab.x + ab.y;
}

// The normal a tangent-space normal map gives (`mapped`: x along the texture's u, y along its v, z
// along the surface normal n) at camera-frame point p with texture coordinates uv, in the frame
// the screen-space derivatives of p and uv span (Schuler, "Normal Mapping without Precomputed
// Tangents", ShaderX5 2006 / 2013): no tangents stored per vertex. The sign of the derivatives'
// determinant keeps the frame right-handed whichever way the image's rows run.
vec3 MappedNormal(vec3 n, vec3 p, vec2 uv, vec3 mapped) {
  vec3 dp1 = dFdx(p);
  vec3 dp2 = dFdy(p);
  vec2 duv1 = dFdx(uv);
  vec2 duv2 = dFdy(uv);
  vec3 dp2perp = cross(dp2, n);
  vec3 dp1perp = cross(n, dp1);
  float orientation = dot(dp1, dp2perp) >= 0.0 ? 1.0 : -1.0;
  vec3 t = (dp2perp * duv1.x + dp1perp * duv2.x) * orientation;
  vec3 b = (dp2perp * duv1.y + dp1perp * duv2.y) * orientation;
  float scale = inversesqrt(max(max(dot(t, t), dot(b, b)), 1e-30));
  return normalize(mat3(t * scale, b * scale, n) * mapped);
}
