// Instanced geometry. Each instance carries T_CO, the object -> camera transform (computed on the CPU in double
// precision per frame, so positions near the camera keep full float precision however far the scene extends),
// and its labels. Camera frame C: x right, y down, z forward (optical).
precision highp float;

layout(location = 0) in vec3 a_p_O;       // vertex position, object frame (m)
layout(location = 1) in vec3 a_n_O;       // vertex normal, object frame
layout(location = 2) in vec2 a_uv;        // texture coordinates
layout(location = 3) in vec4 a_T_CO_0;    // rows of the 3x4 matrix T_CO (rotation * scale | translation)
layout(location = 4) in vec4 a_T_CO_1;
layout(location = 5) in vec4 a_T_CO_2;
layout(location = 6) in uvec2 a_ids;      // (class id, instance id)
layout(location = 7) in vec3 a_base_color; // linear albedo of the part's material
layout(location = 8) in uvec4 a_surface;   // roughness and metalness (1/255), 0, 0
layout(location = 9) in vec2 a_pattern_size_m;

uniform mat4 u_projection;  // camera frame -> clip space (pinhole intrinsics, image rows top-down)
#ifdef SHADOW_CASTER
uniform mat4 u_shadow_from_C;  // camera frame -> the sun's shadow map (the caster pass draws into it)
#endif

out vec3 v_p_C;
out vec3 v_n_C;
out vec2 v_uv;
flat out uvec2 v_ids;
flat out vec3 v_base_color;
#ifndef SHADOW_CASTER
out vec3 v_p_M;                 // position in the mesh's frame, scaled to metres along its axes
out vec3 v_n_M;                 // normal in the mesh's frame
flat out vec3 v_size_M;         // the part's scale along the mesh's axes (a unit box's sides, m)
flat out uvec4 v_surface;
flat out vec2 v_pattern_size_m;
#endif

void main() {
  vec3 c0 = vec3(a_T_CO_0.x, a_T_CO_1.x, a_T_CO_2.x);
  vec3 c1 = vec3(a_T_CO_0.y, a_T_CO_1.y, a_T_CO_2.y);
  vec3 c2 = vec3(a_T_CO_0.z, a_T_CO_1.z, a_T_CO_2.z);
  vec3 t = vec3(a_T_CO_0.w, a_T_CO_1.w, a_T_CO_2.w);
  v_p_C = c0 * a_p_O.x + c1 * a_p_O.y + c2 * a_p_O.z + t;
  // Normals transform with the cofactor matrix det(M) M^-T = [c1 x c2, c2 x c0, c0 x c1], which stays right
  // under non-uniform scale; the sign of det keeps mirrored objects facing out.
  vec3 n = cross(c1, c2) * a_n_O.x + cross(c2, c0) * a_n_O.y + cross(c0, c1) * a_n_O.z;
  v_n_C = n * sign(dot(c0, cross(c1, c2)));
  v_uv = a_uv;
  v_ids = a_ids;
  v_base_color = a_base_color;
#ifndef SHADOW_CASTER
  // The columns' lengths are the part's scale: T_CO is a rotation times that scale.
  v_size_M = vec3(length(c0), length(c1), length(c2));
  v_p_M = a_p_O * v_size_M;
  v_n_M = a_n_O;
  v_surface = a_surface;
  v_pattern_size_m = a_pattern_size_m;
#endif
#ifdef SHADOW_CASTER
  gl_Position = u_shadow_from_C * vec4(v_p_C, 1.0);
#else
  gl_Position = u_projection * vec4(v_p_C, 1.0);
#endif
}
