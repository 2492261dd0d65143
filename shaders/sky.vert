// A full-screen triangle on the far plane (depth 1), drawn after the geometry with depth test LEQUAL so only
// pixels that nothing covered are shaded.
precision highp float;

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
