// One geometry pass writing every requested output into its own render target (OUT_* defines select them).
// RGB: metallic-roughness shading (surface.glsl, prepended) of the sun, shaded by the sun's shadow map,
// and of the sky (hemispheric diffuse light with a cheap contact-darkening term, the mirrored sky for
// the specular part), optional texture, procedural surface patterns, and fog (uniform or thinning with
// height); written linear into an sRGB8 target, which encodes to sRGB.
// Depths: written from the interpolated camera-frame position, not the non-linear depth buffer.
// TEXTURED (0 or 1, defined by the renderer) says whether the parts drawn have maps (colour, normal,
// metallic-roughness), so that untextured ones sample none.
// PATTERN (defined by the renderer) is the surface pattern of every part the program draws: a
// constant, so that the compiler keeps only that pattern's code (llvmpipe runs every branch of a
// shader for every pixel, taken or not: one program holding all patterns cost each pixel all of them).
in vec3 v_p_C;
in vec3 v_n_C;
in vec2 v_uv;
flat in uvec2 v_ids;
flat in vec3 v_base_color;
in vec3 v_p_M;
in vec3 v_n_M;
flat in vec3 v_size_M;
flat in uvec4 v_surface;
flat in vec2 v_pattern_size_m;

#ifdef OUT_RGB
layout(location = 0) out vec4 o_rgb;
#endif
#ifdef OUT_DEPTH_PLANAR
layout(location = 1) out float o_depth_planar;
#endif
#ifdef OUT_DEPTH_PERSPECTIVE
layout(location = 2) out float o_depth_perspective;
#endif
#ifdef OUT_CLASS
layout(location = 3) out uint o_class;
#endif
#ifdef OUT_INSTANCE
layout(location = 4) out uint o_instance;
#endif
#ifdef OUT_NORMAL
layout(location = 5) out vec4 o_normal;
#endif

#if TEXTURED
uniform bool u_has_texture;
uniform mediump sampler2D u_texture;     // sRGB texture, decoded to linear by the sampler
uniform bool u_has_normal_map;
uniform mediump sampler2D u_normal_map;  // tangent space, (n + 1) / 2
uniform float u_normal_scale;             // glTF's normalTexture.scale: multiplies the map's x, y
uniform bool u_has_metallic_roughness_map;
uniform mediump sampler2D u_metallic_roughness_map;  // roughness in green, metalness in blue
#endif
uniform vec3 u_to_sun_C;         // unit vector toward the sun, camera frame
uniform vec3 u_up_C;             // world up (-z of NED), camera frame
uniform float u_camera_height_m; // camera height above the world origin (-z of NED)
uniform vec3 u_sun_rgb;
uniform vec3 u_sky_zenith_rgb;
uniform vec3 u_sky_horizon_rgb;
uniform float u_ambient;         // fraction of the light that comes from the sky
uniform float u_fog_distance_m;  // 0 = no fog; else 1 / the extinction at the world's z = 0
uniform float u_fog_height_m;    // scale height of the fog's density; 0 = the same at every height
uniform float u_rain_extinction_per_m;  // the rain's, uniform
uniform bool u_has_shadow;       // the shadow map below holds this frame's casters
uniform highp sampler2DShadow u_shadow_map;
uniform mat4 u_shadow_from_C;    // camera frame -> the map's clip space
uniform float u_shadow_texel;    // one texel in the map's [0, 1] coordinates
uniform float u_shadow_offset_m; // receivers are looked up this far out along their normal
uniform float u_shadow_distance_m;

// Fraction of the sun that reaches p_C (normal n): 4 taps of the map's 2 x 2 filtered comparison,
// half a texel apart, so edges are soft over about two texels; lit beyond the map and faded to
// lit over the last tenth of the shadow distance.
float SunVisibility(vec3 p_C, vec3 n) {
  if (!u_has_shadow) return 1.0;
  vec4 s = u_shadow_from_C * vec4(p_C + n * u_shadow_offset_m, 1.0);
  vec3 q = s.xyz * 0.5 + 0.5;
  if (q.x <= 0.0 || q.x >= 1.0 || q.y <= 0.0 || q.y >= 1.0 || q.z >= 1.0) return 1.0;
  float d = 0.5 * u_shadow_texel;
  float lit = texture(u_shadow_map, vec3(q.x - d, q.y - d, q.z)) +
              texture(u_shadow_map, vec3(q.x + d, q.y - d, q.z)) +
              texture(u_shadow_map, vec3(q.x - d, q.y + d, q.z)) +
              texture(u_shadow_map, vec3(q.x + d, q.y + d, q.z));
  float fade = smoothstep(0.9 * u_shadow_distance_m, u_shadow_distance_m, length(p_C));
  return mix(0.25 * lit, 1.0, fade);
}

void main() {
  vec3 n = normalize(v_n_C);
  if (!gl_FrontFacing) n = -n;
#ifdef OUT_RGB
  Surface s = Surface(v_base_color, float(v_surface.x) / 255.0, float(v_surface.y) / 255.0);
  vec3 n_geometry = n;
#if TEXTURED
  if (u_has_texture) s.albedo *= texture(u_texture, v_uv).rgb;
  if (u_has_metallic_roughness_map) {
    vec3 mr = texture(u_metallic_roughness_map, v_uv).rgb;
    s.roughness *= mr.g;
    s.metallic *= mr.b;
  }
  if (u_has_normal_map) {
    vec3 mapped = texture(u_normal_map, v_uv).xyz * 2.0 - 1.0;
    n = MappedNormal(n, v_p_C, v_uv, mapped * vec3(u_normal_scale, u_normal_scale, 1.0));
  }
#endif
#if PATTERN != 0
  s = ApplyPattern(s, uint(PATTERN), v_p_M, normalize(v_n_M), v_size_M, v_pattern_size_m, v_ids.y);
#endif
  float roughness = max(s.roughness, 0.02);
  float up = dot(n, u_up_C);
  // Hemispheric ambient: sky colour from above, a warm ground bounce from below.
  vec3 ground_bounce = vec3(0.32, 0.28, 0.24);
  vec3 sky_mean = mix(u_sky_horizon_rgb, u_sky_zenith_rgb, 0.5) * 1.3;
  vec3 sky_light = mix(ground_bounce, sky_mean, 0.5 + 0.5 * up);
  // Contact darkening: walls get darker toward the ground (a cheap stand-in for ambient occlusion).
  float height_m = dot(v_p_C, u_up_C) + u_camera_height_m;
  float occlusion = mix(1.0, mix(0.55, 1.0, clamp(height_m / 4.0, 0.0, 1.0)), 1.0 - abs(up));
  float sun = max(dot(n, u_to_sun_C), 0.0);
  float visibility = sun > 0.0 ? SunVisibility(v_p_C, n) : 0.0;
  vec3 sun_light = (1.0 - u_ambient) * 1.6 * u_sun_rgb;
  vec3 sky_scale = vec3(u_ambient * 1.4 * occlusion);
  // Metallic-roughness (glTF 2.0): metals reflect their base colour and have no diffuse part;
  // dielectrics reflect 4% at normal incidence. Diffuse here is albedo times the light (the
  // Lambertian 1/pi folded into the light's scale), so the sun's specular is pi times the BRDF
  // (SpecularSun).
  vec3 diffuse = s.albedo * (1.0 - s.metallic);
  vec3 f0 = mix(vec3(0.04), s.albedo, s.metallic);
  vec3 view = -normalize(v_p_C);
  vec3 rgb = diffuse * (sun_light * sun * visibility + sky_scale * sky_light);
  if (visibility > 0.0) {
    rgb += sun_light * SpecularSun(n, view, u_to_sun_C, roughness, f0) * visibility;
  }
  // The sky seen in the mirror direction (the ground's bounce below the horizon), blurred toward
  // the sky's mean with roughness: image-based light from the same sky the background shows.
  vec3 r = reflect(-view, n);
  float r_up = dot(r, u_up_C);
  vec3 mirrored = r_up >= 0.0
                      ? mix(u_sky_horizon_rgb, u_sky_zenith_rgb, sqrt(r_up)) * 1.3
                      : ground_bounce;
  rgb += sky_scale * mix(mirrored, sky_mean, roughness) *
         EnvironmentReflectance(max(dot(n, view), 1e-4), roughness, f0);
#if PATTERN == 10
  // Car paint: a clear coat over the layer above (the pigment, and its metallic flakes through the
  // material's metallic and roughness). The coat is a smooth dielectric (roughness 0.05, F0 0.04):
  // it mirrors the sun and the sky sharply and passes on the light it does not reflect.
  {
    const float kCoatRoughness = 0.05;
    vec3 coat = EnvironmentReflectance(max(dot(n, view), 1e-4), kCoatRoughness, vec3(0.04));
    rgb *= 1.0 - coat;
    if (visibility > 0.0) {
      rgb += sun_light * SpecularSun(n, view, u_to_sun_C, kCoatRoughness, vec3(0.04)) * visibility;
    }
    rgb += sky_scale * mirrored * coat;
  }
#endif
  if (u_fog_distance_m > 0.0) {
    // Optical depth from the camera to the surface: d / fog distance, times the mean of the density
    // exp(-h / H) along the segment in height fog: from h_c to h_s = h_c + x H it is
    // (exp(-h_c / H) - exp(-h_s / H)) / x, written so that neither exponential overflows for a
    // camera far above the fog (x near 0: its series). The in-scattered light is the horizon's.
    float tau = length(v_p_C) / u_fog_distance_m;
    if (u_fog_height_m > 0.0) {
      float a = u_camera_height_m / u_fog_height_m;
      float x = dot(v_p_C, u_up_C) / u_fog_height_m;
      float mean = abs(x) > 1e-3 ? (exp(-a) - exp(-(a + x))) / x : exp(-a) * (1.0 - 0.5 * x);
      tau *= mean;
    }
    rgb = mix(rgb, u_sky_horizon_rgb, 1.0 - exp(-tau));
  }
  // Rain: its drops' extinction, uniform along the ray.
  rgb = mix(rgb, u_sky_horizon_rgb, 1.0 - exp(-length(v_p_C) * u_rain_extinction_per_m));
  o_rgb = vec4(rgb, 1.0);
#endif
#ifdef OUT_DEPTH_PLANAR
  o_depth_planar = v_p_C.z;
#endif
#ifdef OUT_DEPTH_PERSPECTIVE
  o_depth_perspective = length(v_p_C);
#endif
#ifdef OUT_CLASS
  o_class = v_ids.x;
#endif
#ifdef OUT_INSTANCE
  o_instance = v_ids.y;
#endif
#ifdef OUT_NORMAL
  o_normal = vec4(n_geometry, 0.0);
#endif
}
