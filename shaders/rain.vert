// Rain streaks (docs/rendering.md, "Rain"). Drop k is placed and sized by hashes of k and the period:
// anywhere in a cube of side u_box_m that wraps around the camera (so the drops stay fixed in the world
// as the camera moves), diameter D >= u_min_diameter_mm from the Marshall-Palmer tail
// D = D_min - ln(1 - q) / lambda, falling at its terminal speed 9.65 - 10.3 exp(-0.6 D) m/s through air
// that moves with the wind (a drop keeps its terminal speed relative to the air). Its streak is
// the segment it falls along during the exposure (centred on the frame's time, as the camera's motion
// blur), a quad one pixel wide, drawn as a triangle strip of
// four vertices per instance with the scene's depth test (a drop behind a wall is hidden).
precision highp float;

uniform mat4 u_projection;
uniform mat3 u_R_CW;             // world -> camera rotation
uniform vec3 u_camera_mod_m;     // the camera's world position modulo u_box_m
uniform float u_box_m;
uniform float u_time_s;          // time within the period (the drops are redrawn each period)
uniform uint u_seed;             // the seed and the period
uniform float u_min_diameter_mm;
uniform float u_slope_per_mm;    // Marshall-Palmer lambda
uniform float u_exposure_s;      // the camera's exposure time (CameraEffectsConfig::exposure_time_s)
uniform vec3 u_wind_W;           // the air's velocity at the camera, world NED (m/s)
uniform vec2 u_pixel_ndc;        // one pixel in normalized device coordinates (2 / width, 2 / height)
uniform float u_pixel_rad;       // one pixel's angle at the image centre

out float v_alpha;

uint Hash(uint x) {
  x ^= x >> 16;
  x *= 0x7FEB352Du;
  x ^= x >> 15;
  x *= 0x846CA68Bu;
  x ^= x >> 16;
  return x;
}

float Uniform01(inout uint state) {
  state = Hash(state);
  return float(state >> 8) * (1.0 / 16777216.0);
}

void main() {
  uint state = uint(gl_InstanceID) * 0x9E3779B1u ^ u_seed;
  vec3 q = vec3(Uniform01(state), Uniform01(state), Uniform01(state));
  float diameter_mm = u_min_diameter_mm - log(1.0 - Uniform01(state)) / u_slope_per_mm;
  float speed = 9.65 - 10.3 * exp(-0.6 * diameter_mm);
  vec3 velocity_W = u_wind_W + vec3(0.0, 0.0, speed);
  vec3 p = q * u_box_m + velocity_W * u_time_s - u_camera_mod_m;
  p = mod(p + 0.5 * u_box_m, u_box_m) - 0.5 * u_box_m;  // relative to the camera, world axes
  vec3 half_fall = 0.5 * u_exposure_s * velocity_W;
  vec3 end_C = u_R_CW * (p + half_fall);
  vec3 start_C = u_R_CW * (p - half_fall);
  if (end_C.z < 0.2 || start_C.z < 0.2) {  // behind or at the lens: not drawn
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_alpha = 0.0;
    return;
  }
  vec4 a = u_projection * vec4(end_C, 1.0);
  vec4 b = u_projection * vec4(start_C, 1.0);
  vec2 along = b.xy / b.w - a.xy / a.w;
  vec2 along_px = along / u_pixel_ndc;
  float length_px = length(along_px);
  vec2 dir = length_px > 1e-3 ? along_px / length_px : vec2(1.0, 0.0);
  vec2 side = vec2(-dir.y, dir.x) * 0.5 * u_pixel_ndc;
  // The drop covers min(1, its width in pixels) of a pixel while it crosses it, 1 / length of the
  // exposure: the streak's opacity.
  float distance_m = 0.5 * (length(end_C) + length(start_C));
  float width_px = diameter_mm * 1e-3 / (distance_m * u_pixel_rad);
  v_alpha = min(width_px, 1.0) / max(length_px, 1.0);
  int corner = gl_VertexID;
  vec4 at = corner < 2 ? a : b;
  float s = (corner & 1) == 0 ? -1.0 : 1.0;
  gl_Position = vec4(at.xy + s * side * at.w, at.zw);
}
