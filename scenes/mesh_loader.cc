#include "scenes/mesh_loader.h"

#include <assimp/GltfMaterial.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "engine/core/limits.h"
#include "engine/render/texture_file.h"
#include "engine/scene/primitive_meshes.h"
#include "scenes/mesh_file_check.h"

namespace airis::scenes {

namespace fs = std::filesystem;

namespace {

constexpr engine::EnumName<MeshAxes> kMeshAxesNames[] = {
    {MeshAxes::kYUp, "y_up"}, {MeshAxes::kZUp, "z_up"}, {MeshAxes::kNed, "ned"}};

/// Rotation from file axes to the model frame (both right-handed, so windings are kept).
Eigen::Matrix3f AxesRotation(MeshAxes axes) {
  Eigen::Matrix3f R;
  switch (axes) {
    case MeshAxes::kYUp:  // north = -z, east = x, down = -y
      R << 0, 0, -1, 1, 0, 0, 0, -1, 0;
      break;
    case MeshAxes::kZUp:  // north = x, east = -y, down = -z
      R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
      break;
    case MeshAxes::kNed:
      R.setIdentity();
      break;
  }
  return R;
}

// The image of embedded texture `name` ("*N") of `scene`: the bytes of the PNG or JPEG file the
// mesh file holds (glTF's images always are), "" when there is none. Sets `raw` when the texture
// is raw texels instead (assimp's mHeight > 0, from other formats).
std::string EmbeddedImage(const aiScene& scene, const std::string& name, bool* raw) {
  const aiTexture* t = scene.GetEmbeddedTexture(name.c_str());
  *raw = t != nullptr && t->mHeight != 0;
  if (t == nullptr || t->pcData == nullptr || *raw) return "";
  return std::string(reinterpret_cast<const char*>(t->pcData), t->mWidth);
}

// The texture of the first of `types` that material `in` (named `material`) of the mesh file at
// `mesh_path` names, "" when it names none: the absolute path of an image file, or for an image
// embedded in the file (a GLB's) the name "MESH_PATH#*N" under which its bytes go
// into `images`. Throws MeshLoadError when the file is missing or no image the renderer reads.
std::string TexturePath(const aiScene& scene, const aiMaterial& in,
                        std::initializer_list<aiTextureType> types, const std::string& material,
                        const std::string& mesh_path, std::map<std::string, std::string>& images) {
  aiString texture;
  for (aiTextureType type : types) {
    if (in.GetTexture(type, 0, &texture) == AI_SUCCESS) break;
    texture.Clear();
  }
  const std::string t = texture.C_Str();
  if (t.empty()) return "";
  if (t[0] == '*') {
    const std::string name = mesh_path + "#" + t;
    if (images.count(name) != 0) return name;
    bool raw = false;
    std::string image = EmbeddedImage(scene, t, &raw);
    const std::string problem =
        raw ? "raw texels, not a PNG or JPEG image (airis reads embedded images of those two)"
        : image.empty() ? "the file holds no such image"
                        : engine::CheckTextureBytes(image);
    if (!problem.empty()) {
      throw MeshLoadError("embedded texture " + t + " (named by material '" + material +
                          "'): " + problem);
    }
    images.emplace(name, std::move(image));
    return name;
  }
  const fs::path resolved = (fs::path(mesh_path).parent_path() / t).lexically_normal();
  if (!fs::is_regular_file(resolved)) {
    throw MeshLoadError("texture file not found: " + resolved.string() + " (named by material '" +
                        material + "' of " + mesh_path + ")");
  }
  const std::string problem = engine::CheckTextureFile(resolved.string());
  if (!problem.empty()) {
    throw MeshLoadError("texture " + resolved.string() + " (named by material '" + material +
                        "'): " + problem);
  }
  return fs::absolute(resolved).string();
}

engine::Material ReadMaterial(const aiScene& scene, const aiMaterial& in,
                              const std::string& mesh_path,
                              std::map<std::string, std::string>& images) {
  engine::Material out;
  aiString name;
  if (in.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  aiColor4D color;
  if (in.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
      in.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) {
    out.base_color_rgb = Eigen::Vector3f(color.r, color.g, color.b).cwiseMax(0.0f).cwiseMin(1.0f);
  }
  // glTF 2.0's metallic-roughness factors (pbrMetallicRoughness; the format's defaults are 1 and
  // 1). Other formats keep the default rough dielectric: their importers' guesses differ.
  const std::string extension = fs::path(mesh_path).extension().string();
  const bool gltf =
      extension == ".gltf" || extension == ".glb" || extension == ".GLTF" || extension == ".GLB";
  if (gltf) {
    float factor = 1.0f;
    if (in.Get(AI_MATKEY_ROUGHNESS_FACTOR, factor) == AI_SUCCESS) {
      out.roughness = std::clamp(factor, 0.02f, 1.0f);
    }
    if (in.Get(AI_MATKEY_METALLIC_FACTOR, factor) == AI_SUCCESS) {
      out.metallic = std::clamp(factor, 0.0f, 1.0f);
    }
  }
  out.texture_path = TexturePath(scene, in, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE},
                                 out.name, mesh_path, images);
  if (gltf) {
    // glTF 2.0's normal and metallic-roughness maps (assimp files the latter as metalness).
    out.normal_texture_path =
        TexturePath(scene, in, {aiTextureType_NORMALS}, out.name, mesh_path, images);
    float scale = 1.0f;
    if (!out.normal_texture_path.empty() &&
        in.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), scale) == AI_SUCCESS) {
      if (!std::isfinite(scale)) {
        throw MeshLoadError("normalTexture.scale of material '" + out.name + "' is not finite");
      }
      out.normal_scale = scale;
    }
    out.metallic_roughness_texture_path =
        TexturePath(scene, in, {aiTextureType_METALNESS}, out.name, mesh_path, images);
  }
  return out;
}

/// Vertices and faces of the scene once every node's meshes are placed (what pre-transforming
/// makes: a mesh used by many nodes is copied for each), refused beyond the limits before that.
void CheckPlacedCounts(const aiScene& scene) {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::vector<const aiNode*> pending{scene.mRootNode};
  while (!pending.empty()) {
    const aiNode* node = pending.back();
    pending.pop_back();
    if (node == nullptr) continue;
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      if (node->mMeshes[k] >= scene.mNumMeshes) continue;
      vertices += scene.mMeshes[node->mMeshes[k]]->mNumVertices;
      faces += scene.mMeshes[node->mMeshes[k]]->mNumFaces;
    }
    if (vertices > engine::kMaxMeshVertices || faces > engine::kMaxMeshTriangles) {
      throw MeshLoadError("its nodes place more than " + std::to_string(engine::kMaxMeshVertices) +
                          " vertices or " + std::to_string(engine::kMaxMeshTriangles) +
                          " faces (the limits per mesh file, docs/limits.md)");
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) pending.push_back(node->mChildren[c]);
  }
}

}  // namespace

std::span<const engine::EnumName<MeshAxes>> EnumNames(MeshAxes) { return kMeshAxesNames; }

MeshFile LoadMeshFile(const std::string& path, MeshAxes axes) {
  CheckMeshFileBeforeImport(path);
  Assimp::Importer importer;
  // Keep only triangles: points and lines have no surface to collide with or draw.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  // Read first, then check what placing every node's meshes would make, then process.
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (scene == nullptr) throw MeshLoadError(importer.GetErrorString());
  CheckPlacedCounts(*scene);
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                       aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices |
                                       aiProcess_SortByPType | aiProcess_FindInvalidData);
  if (scene == nullptr) throw MeshLoadError(importer.GetErrorString());
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mNumMeshes == 0) {
    throw MeshLoadError("the file contains no triangle meshes");
  }
  const Eigen::Matrix3f R = AxesRotation(axes);
  MeshFile out;
  for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
    out.materials.push_back(ReadMaterial(*scene, *scene->mMaterials[m], path, out.images));
  }
  if (out.materials.empty()) out.materials.emplace_back();
  std::size_t triangles = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh& in = *scene->mMeshes[i];
    if ((in.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0 || in.mNumFaces == 0) continue;
    engine::TriangleMesh mesh;
    mesh.name = path + (scene->mNumMeshes > 1 ? "#" + std::to_string(i) : "");
    mesh.positions.reserve(in.mNumVertices);
    mesh.normals.reserve(in.mNumVertices);
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
      const aiVector3D& p = in.mVertices[v];
      mesh.positions.push_back(R * Eigen::Vector3f(p.x, p.y, p.z));
      const aiVector3D n = in.HasNormals() ? in.mNormals[v] : aiVector3D(0, 0, 1);
      mesh.normals.push_back((R * Eigen::Vector3f(n.x, n.y, n.z)).normalized());
    }
    if (in.HasTextureCoords(0)) {
      mesh.uvs.reserve(in.mNumVertices);
      for (unsigned v = 0; v < in.mNumVertices; ++v) {
        mesh.uvs.emplace_back(in.mTextureCoords[0][v].x, in.mTextureCoords[0][v].y);
      }
    }
    mesh.indices.reserve(3 * in.mNumFaces);
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.indices.insert(mesh.indices.end(),
                          {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    triangles += mesh.triangle_count();
    engine::UpdateBounds(mesh);
    const std::size_t material = in.mMaterialIndex < out.materials.size() ? in.mMaterialIndex : 0;
    out.parts.push_back({out.meshes.size(), material});
    out.meshes.push_back(std::move(mesh));
  }
  if (triangles == 0) throw MeshLoadError("the file contains no triangles");
  if (triangles > engine::kMaxMeshTriangles) {
    throw MeshLoadError("the file has " + std::to_string(triangles) +
                        " triangles, more than the limit of " +
                        std::to_string(engine::kMaxMeshTriangles) + " (docs/limits.md)");
  }
  return out;
}

}  // namespace airis::scenes
