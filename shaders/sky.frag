// Sky gradient from the horizon to the zenith along each pixel's ray, a soft sun glow, and a hazy band below
// the horizon. Only the RGB target is bound for this pass.
precision highp float;

layout(location = 0) out vec4 o_rgb;

uniform vec4 u_intrinsics;  // (fx, fy, cx, cy) of the rendered (undistorted) image, pixels
uniform vec3 u_to_sun_C;
uniform vec3 u_up_C;
uniform vec3 u_sun_rgb;
uniform vec3 u_sky_zenith_rgb;
uniform vec3 u_sky_horizon_rgb;

void main() {
  // Window coordinates are image coordinates shifted by half a pixel (rows run top-down, see u_projection).
  vec2 uv = gl_FragCoord.xy - 0.5;
  vec3 ray = normalize(vec3((uv.x - u_intrinsics.z) / u_intrinsics.x,
                            (uv.y - u_intrinsics.w) / u_intrinsics.y, 1.0));
  float elevation = dot(ray, u_up_C);
  vec3 rgb;
  if (elevation >= 0.0) {
    rgb = mix(u_sky_horizon_rgb, u_sky_zenith_rgb, sqrt(elevation));
  } else {
    rgb = u_sky_horizon_rgb * mix(0.9, 0.6, sqrt(-elevation));
  }
  float glow = max(dot(ray, u_to_sun_C), 0.0);
  rgb += u_sun_rgb * (0.25 * pow(glow, 8.0) + 2.0 * pow(glow, 800.0));
  o_rgb = vec4(rgb, 1.0);
}
