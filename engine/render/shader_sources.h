#pragma once

#include <string_view>

namespace airis::engine::shaders {

// GLSL ES 3.00 sources from shaders/, compiled into the library at build time
// (engine/render/CMakeLists.txt). Each lacks its `#version` line: the renderer prepends `#version
// 300 es` and the `#define`s of a variant.

/// shaders/scene.vert: instanced geometry, positions and normals into the camera frame.
extern const std::string_view k_scene_vert;
/// shaders/surface.glsl: procedural surface patterns and metallic-roughness reflectance, prepended
/// to scene.frag.
extern const std::string_view k_surface_glsl;
/// shaders/scene.frag: shading, depths, labels and normals into multiple render targets.
extern const std::string_view k_scene_frag;
/// shaders/shadow.frag: depth only, for the sun's shadow map (scene.vert with SHADOW_CASTER).
extern const std::string_view k_shadow_frag;
/// shaders/sky.vert: a full-screen triangle at the far plane.
extern const std::string_view k_sky_vert;
/// shaders/sky.frag: the sky gradient and sun glow behind the geometry.
extern const std::string_view k_sky_frag;
extern const std::string_view k_rain_vert;
extern const std::string_view k_rain_frag;
/// shaders/remap.frag: applies lens distortion by looking up each output pixel in the undistorted
/// render.
extern const std::string_view k_remap_frag;

}  // namespace airis::engine::shaders
