// Lens distortion: each output (distorted) pixel looks up where its ray lands in the undistorted render
// (u_map, computed on the CPU by inverting the Brown-Conrady model) and copies that sample. RGB is filtered
// bilinearly; depths, labels and normals take the nearest texel so every value belongs to a real surface.
precision highp float;
precision highp int;

#ifdef OUT_RGB
layout(location = 0) out vec4 o_rgb;
uniform mediump sampler2D u_rgb;
#endif
#ifdef OUT_DEPTH_PLANAR
layout(location = 1) out float o_depth_planar;
uniform highp sampler2D u_depth_planar;
#endif
#ifdef OUT_DEPTH_PERSPECTIVE
layout(location = 2) out float o_depth_perspective;
uniform highp sampler2D u_depth_perspective;
#endif
#ifdef OUT_CLASS
layout(location = 3) out uint o_class;
uniform highp usampler2D u_class;
#endif
#ifdef OUT_INSTANCE
layout(location = 4) out uint o_instance;
uniform highp usampler2D u_instance;
#endif
#ifdef OUT_NORMAL
layout(location = 5) out vec4 o_normal;
uniform highp sampler2D u_normal;
#endif

uniform highp sampler2D u_map;  // RG32F: undistorted image coordinates (pixel centres at integers)
uniform vec2 u_source_size;     // size of the undistorted render, pixels

void main() {
  vec2 source = texelFetch(u_map, ivec2(gl_FragCoord.xy), 0).xy;
  ivec2 nearest = ivec2(floor(source + 0.5));
#ifdef OUT_RGB
  o_rgb = texture(u_rgb, (source + 0.5) / u_source_size);
#endif
#ifdef OUT_DEPTH_PLANAR
  o_depth_planar = texelFetch(u_depth_planar, nearest, 0).r;
#endif
#ifdef OUT_DEPTH_PERSPECTIVE
  o_depth_perspective = texelFetch(u_depth_perspective, nearest, 0).r;
#endif
#ifdef OUT_CLASS
  o_class = texelFetch(u_class, nearest, 0).r;
#endif
#ifdef OUT_INSTANCE
  o_instance = texelFetch(u_instance, nearest, 0).r;
#endif
#ifdef OUT_NORMAL
  o_normal = texelFetch(u_normal, nearest, 0);
#endif
}
