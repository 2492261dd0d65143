// The checks that mesh files pass before assimp reads them (scenes/mesh_file_check.h): valid files
// of each format load; each rule of the PLY and STL grammars refuses what breaks it, with a reason.
#include "scenes/mesh_file_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scenes/mesh_loader.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;

// The tests run in the source folder (tests/scenes/CMakeLists.txt).
const fs::path kMeshSeeds = fs::path("tests") / "fuzz" / "corpus" / "mesh";

std::string Load(const fs::path& path) {
  try {
    const MeshFile mesh = LoadMeshFile(path.string(), MeshAxes::kNed);
    std::size_t triangles = 0;
    for (const auto& m : mesh.meshes) triangles += m.triangle_count();
    return "ok " + std::to_string(triangles);
  } catch (const MeshLoadError& e) {
    return e.what();
  }
}

std::string LoadText(const std::string& extension, const std::string& bytes) {
  return Load(testing::WriteTempFile("mesh." + extension, bytes));
}

template <class T>
std::string Bytes(T value, bool big_endian = false) {
  std::string out(sizeof value, '\0');
  std::memcpy(out.data(), &value, sizeof value);
  if (big_endian) std::reverse(out.begin(), out.end());
  return out;
}

// The minimal triangle of each format kept as fuzz seeds (tests/fuzz/make_corpus.py): the seed's
// first byte names the extension, the rest is the file.
TEST(MeshFileCheckTest, MinimalMeshOfEachFormatLoadsAsOneTriangle) {
  const auto extensions = MeshFileExtensions();
  std::vector<std::string> seen;
  for (const auto& entry : fs::directory_iterator(kMeshSeeds)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("gen_minimal_", 0) != 0) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string seed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(seed.empty());
    const std::string extension = extensions[static_cast<unsigned char>(seed[0])];
    if (extension == "fbx") continue;  // no minimal FBX is kept (a binary format of its own)
    EXPECT_EQ(LoadText(extension, seed.substr(1)), "ok 1") << name;
    seen.push_back(extension);
  }
  EXPECT_EQ(seen.size(), 8u) << "obj, gltf, glb, dae, ASCII and binary PLY and STL";
}

const std::string kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kPlyVertices = "0 0 0\n1 0 0\n0 1 0\n";

TEST(MeshFileCheckTest, BigAndLittleEndianPlyGiveTheSameTriangle) {
  for (const bool big : {false, true}) {
    std::string ply =
        std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    for (const float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) ply += Bytes(v, big);
    ply += '\3' + Bytes(std::int32_t{0}, big) + Bytes(std::int32_t{1}, big) +
           Bytes(std::int32_t{2}, big);
    const fs::path path = testing::WriteTempFile("endian.ply", ply);
    const MeshFile mesh = LoadMeshFile(path.string(), MeshAxes::kNed);
    ASSERT_EQ(mesh.meshes.size(), 1u);
    EXPECT_FLOAT_EQ(mesh.meshes[0].bounds.max().x(), 1.0f) << (big ? "big" : "little");
    EXPECT_FLOAT_EQ(mesh.meshes[0].bounds.max().y(), 1.0f) << (big ? "big" : "little");
  }
}

struct Refusal {
  const char* extension;
  std::string bytes;
  const char* fragment;
};

/// Loads each case's bytes as a file of its extension and expects its fragment in the outcome
/// ("ok N" for N triangles, else the error).
template <std::size_t N>
void ExpectEach(const Refusal (&cases)[N]) {
  for (const Refusal& c : cases) {
    const std::string got = LoadText(c.extension, c.bytes);
    EXPECT_NE(got.find(c.fragment), std::string::npos) << c.fragment << "\ngot: " << got;
  }
}

TEST(MeshFileCheckTest, BrokenPlyAndStlAreRefusedWithTheirReason) {
  const std::string binary_stl_header(80, ' ');
  std::string binary_stl_triangle;  // normal, three corners, attribute bytes
  for (const float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
    binary_stl_triangle += Bytes(v);
  }
  binary_stl_triangle += std::string(2, '\0');
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 "
      "0\nendloop\nendfacet\n";
  const Refusal cases[] = {
      {"ply", kPlyHeader + kPlyVertices + "3 0 1 3\n",
       "PLY face 0 names vertex 3, but the file has 3 vertices"},
      {"ply", kPlyHeader + kPlyVertices + "3 0 -1 2\n", "PLY face 0 names vertex -1"},
      {"ply", kPlyHeader + kPlyVertices + "2 0 1\n", "a face needs at least 3 corners"},
      {"ply", kPlyHeader + kPlyVertices + "3 0 1 2 7\n", "PLY face 0 has 5 values, more than"},
      {"ply", kPlyHeader + kPlyVertices + "3 0 1\n", "PLY face 0 has fewer values"},
      {"ply", kPlyHeader + kPlyVertices, "elements, more than the 18 bytes after it can hold"},
      {"ply", kPlyHeader + "0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n",
       "PLY vertex 2: 'one' is not a number"},
      {"ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 "
       "0\n",
       "the PLY element 'vertex' has no scalar property 'z'"},
      {"ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty "
       "float z\n"
       "element face 99\nend_header\n",
       "the PLY element 'face' has no properties"},
      {"ply", "ply\nformat ascii 1.0\nelement camera 1\nproperty float x\nend_header\n0\n",
       "PLY header line 3: an element 'camera' (assimp 5.2.5 reads vertex, face"},
      {"ply", "ply\nformat ascii 1.0\nelemnt vertex 3\nend_header\n",
       "PLY header line 3: unknown keyword 'elemnt'"},
      {"ply", "ply\nformat ascii 2.0\nend_header\n", "PLY header line 2: expected 'format"},
      {"ply", "plyx\nformat ascii 1.0\nend_header\n", "not a PLY file"},
      {"stl", "solid t\n" + facet + "endsolid t\n", "ok 1"},
      {"stl",
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "vertex 1 1 0\nendloop\nendfacet\nendsolid t\n",
       "ASCII STL line 7: expected 'endloop' (got 'vertex')"},
      {"stl", "solid t\n" + facet, "'endsolid' missing"},
      {"stl", "solid t\nfacet normal 0 0\nouter loop\n",
       "ASCII STL line 2: expected 3 numbers after 'facet'"},
      {"stl", "solid t\n" + facet + "endsolid t\n" + std::string(1, '\0'),
       "an ASCII STL file with a NUL byte"},
      {"stl", "solid t\nendsolid t\n", "an ASCII STL file without facets"},
      {"stl", binary_stl_header + Bytes(std::uint32_t{0}), "a binary STL file of no triangles"},
      {"stl", binary_stl_header + Bytes(std::uint32_t{1}) + binary_stl_triangle, "ok 1"},
      {"stl", binary_stl_header + Bytes(std::uint32_t{1}) + binary_stl_triangle + '\0',
       "the header declares 1 triangles (134 bytes) but the file has 135"},
  };
  ExpectEach(cases);
}

// Each rule of the OBJ grammar (scenes/mesh_file_check_obj.h): what assimp 5.2.5 would misread,
// throw on (leaking what it built) or read out of bounds on is refused with its line.
TEST(MeshFileCheckTest, BrokenObjIsRefusedWithItsLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const Refusal cases[] = {
      {"obj", tri + "f 1 2 3\n", "ok 1"},
      {"obj", "# a comment\r\n" + tri + "\r\nvt 0 0\r\nvt 1 0\r\nvt 0 1\r\nf 1/1 2/2 3/3\r\n",
       "ok 1"},
      {"obj", tri + "vn 0 0 1\nf 1//1 2//1 3//1\n", "ok 1"},
      {"obj", "v 0 0 0 1\nv 1 0 0 2\nv 0 1 0 1\nf -3 -2 -1\n", "ok 1"},
      {"obj", tri + "f 1 2 0\n", "OBJ line 4: 'f' corner '0' is not of the form"},
      {"obj", tri + "f 1 2 4\n", "OBJ line 4: index 4 names no position (v): the file has 3"},
      {"obj", tri + "f 1 2 -4\n", "OBJ line 4: index 4 from the end names no position (v)"},
      {"obj", tri + "f 1 2\n", "OBJ line 4: 'f' with 2 corners (at least 3)"},
      {"obj", tri + "l 1\n", "OBJ line 4: 'l' with 1 corners (at least 2)"},
      {"obj", tri + "p 1/1\n", "OBJ line 4: 'p' corner '1/1': a point names a position (v) only"},
      {"obj", tri + "vt 0 0\nf 1/1 2 3\n",
       "OBJ line 5: 'f' corner '2' is not of the form of the statement's first corner '1/1'"},
      {"obj", tri + "f 1/1/1/1 2 3\n", "OBJ line 4: 'f' corner '1/1/1/1' is not of the form"},
      {"obj", tri + "f 1 2 3 # end\n", "OBJ line 4: 'f' corner '#' is not of the form"},
      {"obj", tri + "vt 0\n", "OBJ line 4: 'vt' with 1 numbers (expected 2 or 3)"},
      {"obj", tri + "vn 0 0\n", "OBJ line 4: 'vn' with 2 numbers (expected 3)"},
      {"obj", "v 0 0 0 0 0\n", "OBJ line 1: 'v' with 5 numbers (expected 3, 4 or 6"},
      {"obj", "v 0 0 0 1 1 1 1\n", "OBJ line 1: 'v' with 7 numbers"},
      {"obj", "v 0 0 0 0\n", "OBJ line 1: 'v' with a weight w of 0"},
      {"obj", "v 0 0 nan\n", "OBJ line 1: 'v' holds 'nan' where a number belongs"},
      {"obj", "v 0 0 +-1\n", "OBJ line 1: 'v' holds '+-1' where a number belongs"},
      {"obj", "v 0 0 .5\n", "OBJ line 1: 'v' holds '.5' where a number belongs"},
      {"obj", "v 0 0 -.5\nv 1 0 +0.5\nv 0 1 1e-3\nf 1 2 3\n", "ok 1"},
      {"obj", "v 0 0 1e999\n", "OBJ line 1: 'v' holds '1e999' where a number belongs"},
      {"obj", "v 0 0 0 1 1 1\nv 1 0 0\n", "vertex colours on some vertices only"},
      {"obj", "vtx 0 0\n", "OBJ line 1: unknown or unsupported OBJ statement 'vtx'"},
      {"obj", tri + "lod 0\n", "OBJ line 4: unknown or unsupported OBJ statement 'lod'"},
      {"obj", tri + "cstype bspline\n", "unknown or unsupported OBJ statement 'cstype'"},
      {"obj", tri + " f 1 2 3\n", "OBJ line 4: a statement indented with white space"},
      {"obj", tri + "f 1 2 \\\n3\n", "OBJ line 4: a line continued with '\\'"},
      {"obj", tri + "f 1\v2 3\n", "OBJ line 4: a control character (byte 0x0b"},
      {"obj", tri + "usemtl\n", "OBJ line 4: 'usemtl' without a material name"},
      {"obj", "mtllib\n" + tri, "OBJ line 1: 'mtllib' without a file name"},
      {"obj", "mtllib nothing_here.mtl\n" + tri,
       "'mtllib' names 'nothing_here.mtl', which is not a file"},
      {"obj", "mtllib mesh.obj\n" + tri, "'mtllib' names 'mesh.obj', not a .mtl file"},
      {"obj", "mtllib m.mtl \n" + tri, "'mtllib' file name 'm.mtl ' ends in white space"},
  };
  ExpectEach(cases);
}

// The material library an OBJ names is read as strictly: statements assimp 5.2.5 would write
// through a null material, throw on, or misread are refused, naming the MTL file and its line.
TEST(MeshFileCheckTest, BrokenMtlIsRefusedWithItsLine) {
  const std::string obj = "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const struct {
    std::string mtl;
    const char* fragment;
  } cases[] = {
      {"# materials\nnewmtl a\n  Kd 0.5 0.5 0.5\n  Ns 10\n  illum 2\n  d 1\n  sharpness 60\n",
       "ok 1"},
      {"newmtl a\nmap_Kd -bm 0.5 -o 0 0 0 -clamp on tex.png\n", "texture file not found"},
      {"Kd 1 1 1\nnewmtl a\n", "MTL file m.mtl line 1: 'Kd' before the first 'newmtl'"},
      {"aniso 1\n", "MTL file m.mtl line 1: 'aniso' before the first 'newmtl'"},
      {"newmtl a\naniso 1\n",
       "MTL file m.mtl line 2: unknown or unsupported MTL statement 'aniso'"},
      {"newmtl a\ndecal x.png\n", "unknown or unsupported MTL statement 'decal'"},
      {"newmtl a\nKd 1 1\n", "MTL file m.mtl line 2: 'Kd' with 2 numbers (expected 1 or 3)"},
      {"newmtl a\nNs high\n", "MTL file m.mtl line 2: 'Ns' holds 'high' where a number belongs"},
      {"newmtl a\nillum 12\n", "'illum' takes one whole number from 0 to 10"},
      {"newmtl a\nmap_Kd -bm x tex.png\n", "'map_Kd' holds 'x' where a number belongs"},
      {"newmtl a\nmap_Kd -s 2 tex.png\n", "texture option '-s' needs 3 value(s)"},
      {"newmtl a\nmap_Kd -zoom 2 tex.png\n", "unknown texture option '-zoom'"},
      {"newmtl a\nmap_Kd\n", "'map_Kd' without a file name"},
      {"  newmtl a\n", "MTL file m.mtl line 1: a statement indented with white space"},
      {"newmtl\n", "MTL file m.mtl line 1: 'newmtl' without a material name"},
  };
  const fs::path dir = testing::MakeTempFolder("mtl");
  for (const auto& c : cases) {
    std::ofstream(dir / "m.mtl", std::ios::binary) << c.mtl;
    std::ofstream(dir / "mesh.obj", std::ios::binary) << obj;
    const std::string got = Load(dir / "mesh.obj");
    EXPECT_NE(got.find(c.fragment), std::string::npos) << c.fragment << "\ngot: " << got;
  }
}

// assimp 5.2.5 reads a .gltf file as glTF 2.0 JSON and a .glb file as binary glTF only when the
// JSON declares version 2; otherwise it offers the file to every reader by content, and one that
// airis never checked (the OBJ reader, when "usemtl" appears early on) would read it.
TEST(MeshFileCheckTest, GltfThatIsNotGltf2OfItsFormIsRefused) {
  const std::string v2 = R"({"asset":{"version":"2.0"}})";
  const Refusal cases[] = {
      {"gltf", "{}", "the glTF JSON does not declare glTF 2.0"},
      {"gltf", std::string("{}\0\nusemtl m\nv 0 0 0\n", 21), "does not declare glTF 2.0"},
      {"gltf", R"({"asset":{"version":"1.0"}})", "does not declare glTF 2.0"},
      {"gltf", R"({"asset":{"version":2.0}})", "does not declare glTF 2.0"},
      {"gltf", R"({"asset":"2.0"})", "does not declare glTF 2.0"},
      {"gltf", "glTF" + Bytes(std::uint32_t{2}) + Bytes(std::uint32_t{20}) + v2,
       "a binary glTF (GLB) file named .gltf (name it .glb)"},
      {"glb", v2, "not a GLB file"},
      // Declared glTF 2.0 with nothing in it: assimp's glTF 2.0 reader takes it (its own error).
      {"gltf", v2, "GLTF: No scene"},
  };
  ExpectEach(cases);
}

// ASCII FBX is tokenized and parsed as assimp 5.2.5 does (scenes/mesh_file_check_fbx.h); where
// assimp's parser would stop with an error (leaking the elements it read), airis refuses first.
TEST(MeshFileCheckTest, BrokenAsciiFbxIsRefusedWithItsLine) {
  const std::string head = "; FBX 7.3.0 project file\nFBXHeaderExtension:  {\n";
  std::string deep = "FBXHeaderExtension: ";
  for (int i = 0; i < 70; ++i) deep += "k: {\n";
  const Refusal cases[] = {
      // Read by assimp, which finds no FBXVersion: past airis's grammar.
      {"fbx", head + "\tList: 1,2,\n3\n\tCreator: \"x y\"\n}\n", "FBX-Parser"},
      {"fbx", head + " a: 1\n", "ASCII FBX line 3: the file ends after a value"},
      {"fbx", head + " a:\n", "ASCII FBX line 3: the file ends inside an element"},
      {"fbx", head + " a: b\"c\"\n}\n", "ASCII FBX line 3: a '\"' inside a value"},
      {"fbx", head + " : 1\n}\n", "ASCII FBX line 3: a ':' without a key name before it"},
      {"fbx", head + "}\n1\n", "ASCII FBX line 4: expected a key"},
      {"fbx", head + " a: 1\n\n2\n}\n", "ASCII FBX line 5: a value where '{', '}', ',' or a key"},
      {"fbx", head + " a: x{,\n}\n}\n", "ASCII FBX line 3: a ',' right after '{' or '}'"},
      {"fbx", deep, "scopes nested more than 64 deep"},
  };
  ExpectEach(cases);
}

}  // namespace
}  // namespace airis::scenes
