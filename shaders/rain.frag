// A rain streak: the sky's mean light seen through the drop (a drop refracts most of the sky into the
// camera), blended over the image by the streak's coverage.
precision highp float;

uniform vec3 u_drop_rgb;
in float v_alpha;
layout(location = 0) out vec4 o_rgb;

void main() { o_rgb = vec4(u_drop_rgb, v_alpha); }
