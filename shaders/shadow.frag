// The sun's shadow map: depth only (scene.vert with SHADOW_CASTER places the casters).
precision mediump float;

void main() {}
