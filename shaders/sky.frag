// The sky along each pixel's ray (docs/rendering.md, "Sky and weather"): the gradient sky (horizon to zenith
// colour), Preetham's clear sky (the Perez distribution of Y, x and y; engine/render/daylight.h holds the same
// model on the CPU), or the CIE overcast sky; then the sun's disc and glow, and the height fog along the ray.
// Only the RGB target is bound for this pass.
precision highp float;

layout(location = 0) out vec4 o_rgb;

uniform vec4 u_intrinsics;  // (fx, fy, cx, cy) of the rendered (undistorted) image, pixels
uniform vec3 u_to_sun_C;
uniform vec3 u_up_C;
uniform vec3 u_sun_rgb;
uniform vec3 u_sky_zenith_rgb;
uniform vec3 u_sky_horizon_rgb;
uniform int u_sky_model;            // 0 gradient, 1 clear (Preetham), 2 overcast (CIE)
uniform vec3 u_perez[5];            // clear: A..E for (Y, x, y)
uniform vec3 u_zenith_over_perez;   // clear: zenith (Y display, x, y) / F(0, theta_s)
uniform float u_fog_distance_m;     // 0 = no fog
uniform float u_fog_height_m;       // 0 = uniform fog (the sky is left as it is)
uniform float u_camera_height_m;

vec3 Perez(float cos_theta, float gamma, float cos_gamma) {
  return (1.0 + u_perez[0] * exp(u_perez[1] / cos_theta)) *
         (1.0 + u_perez[2] * exp(u_perez[3] * gamma) + u_perez[4] * cos_gamma * cos_gamma);
}

vec3 XyYToLinearSrgb(vec3 Yxy) {
  float Y = Yxy.x;
  float X = Yxy.y / Yxy.z * Y;
  float Z = (1.0 - Yxy.y - Yxy.z) / Yxy.z * Y;
  return vec3(3.2406 * X - 1.5372 * Y - 0.4986 * Z, -0.9689 * X + 1.8758 * Y + 0.0415 * Z,
              0.0557 * X - 0.2040 * Y + 1.0570 * Z);
}

void main() {
  // Window coordinates are image coordinates shifted by half a pixel (rows run top-down, see u_projection).
  vec2 uv = gl_FragCoord.xy - 0.5;
  vec3 ray = normalize(vec3((uv.x - u_intrinsics.z) / u_intrinsics.x,
                            (uv.y - u_intrinsics.w) / u_intrinsics.y, 1.0));
  float elevation = dot(ray, u_up_C);
  float glow = max(dot(ray, u_to_sun_C), 0.0);
  vec3 rgb;
  if (u_sky_model == 1) {
    // Above the horizon (cos theta at least 0.01, as the CPU model clamps it); below it, the horizon
    // darkened toward the ground as the gradient sky does.
    float cos_theta = max(elevation, 0.01);
    float cos_gamma = clamp(dot(ray, u_to_sun_C), -1.0, 1.0);
    vec3 Yxy = u_zenith_over_perez * Perez(cos_theta, acos(cos_gamma), cos_gamma);
    rgb = max(XyYToLinearSrgb(Yxy), vec3(0.0));
    if (elevation < 0.0) rgb *= mix(0.9, 0.6, sqrt(-elevation));
  } else if (u_sky_model == 2) {
    rgb = u_sky_zenith_rgb * ((1.0 + 2.0 * max(elevation, 0.0)) / 3.0);
    if (elevation < 0.0) rgb *= mix(0.9, 0.6, sqrt(-elevation));
  } else if (elevation >= 0.0) {
    rgb = mix(u_sky_horizon_rgb, u_sky_zenith_rgb, sqrt(elevation));
  } else {
    rgb = u_sky_horizon_rgb * mix(0.9, 0.6, sqrt(-elevation));
  }
  // The sun's disc; and a halo around it, which the clear sky's distribution has already.
  float halo = u_sky_model == 1 ? 0.0 : 0.25 * pow(glow, 8.0);
  rgb += u_sun_rgb * (halo + 2.0 * pow(glow, 800.0));
  if (u_fog_distance_m > 0.0 && u_fog_height_m > 0.0) {
    // Optical depth to infinity through density exp(-h / H) from the camera's height h_c: finite
    // looking up, H exp(-h_c / H) / (fog distance sin(elevation)); at and below the horizon the fog's colour.
    float tau = elevation > 1e-4 ? u_fog_height_m * exp(-u_camera_height_m / u_fog_height_m) /
                                       (u_fog_distance_m * elevation)
                                 : 1e30;
    rgb = mix(u_sky_horizon_rgb, rgb, exp(-tau));
  }
  o_rgb = vec4(rgb, 1.0);
}
