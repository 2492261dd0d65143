#include "scenes/mesh_file_check_obj.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string_view>
#include <system_error>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/limits.h"
#include "scenes/mesh_loader.h"

namespace airis::scenes {

namespace {

namespace fs = std::filesystem;

std::string Count(std::uint64_t n) { return std::to_string(n); }

[[noreturn]] void Refuse(const std::string& problem) { throw MeshLoadError(problem); }

std::string Quote(std::string_view text) { return engine::QuoteValue(text); }

bool IsSeparator(char c) { return c == ' ' || c == '\t'; }

bool IsOneOf(std::string_view word, std::initializer_list<std::string_view> words) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

/// One statement of an OBJ or MTL file as assimp 5.2.5 reads it: the keyword (up to the first
/// space or tab), the arguments (split at runs of spaces and tabs) and the text after the keyword
/// and its separators (what assimp takes as one file name). `at` prefixes its errors.
struct Statement {
  std::string at;
  std::string_view keyword;
  std::vector<std::string_view> args;
  std::string_view rest;
};

enum class Indent { kRefused, kAllowedAfterTheFirstLine };

/// Calls `visit` with each statement of `text`, leaving out blank lines and `#` comments. Lines
/// end at '\n', '\r' or '\f' (assimp's line ends) and are numbered by '\n'. `what` names the file
/// in errors ("OBJ", "MTL file x.mtl").
template <class Visit>
void ForEachStatement(const std::string& what, std::string_view text, Indent indent,
                      Visit&& visit) {
  // A NUL byte anywhere first: assimp 5.2.5 cuts a line there and leaks what it read of a file cut
  // that way (docs/fuzzing.md, "Findings").
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const auto line =
        1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    Refuse(what + " line " + Count(static_cast<std::size_t>(line)) + ": a NUL byte (an " +
           what.substr(0, 3) + " file is text)");
  }
  std::size_t line = 1;
  std::size_t begin = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const bool end = i == text.size();
    if (!end && text[i] != '\n' && text[i] != '\r' && text[i] != '\f') continue;
    std::string_view piece = text.substr(begin, i - begin);
    const std::string at = what + " line " + Count(line) + ": ";
    begin = i + 1;
    const std::size_t this_line = line;
    if (!end && text[i] == '\n') ++line;
    for (const char c : piece) {
      const auto byte = static_cast<unsigned char>(c);
      if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
        static constexpr char kHex[] = "0123456789abcdef";
        Refuse(at + "a control character (byte 0x" + kHex[byte >> 4] + kHex[byte & 15] +
               "; the file is text)");
      }
    }
    if (!piece.empty() && piece.back() == '\\') {
      Refuse(at + "a line continued with '\\' (airis reads one statement per line)");
    }
    const std::size_t first = piece.find_first_not_of(" \t");
    if (first == std::string_view::npos || piece[first] == '#') continue;
    if (first > 0 && (indent == Indent::kRefused || this_line == 1)) {
      Refuse(at +
             "a statement indented with white space (assimp 5.2.5 skips such lines; start it "
             "at the line's first character)");
    }
    piece.remove_prefix(first);
    Statement s;
    s.at = at;
    const std::size_t space = std::min(piece.find_first_of(" \t"), piece.size());
    s.keyword = piece.substr(0, space);
    std::size_t k = space;
    while (k < piece.size() && IsSeparator(piece[k])) ++k;
    s.rest = piece.substr(k);
    while (k < piece.size()) {
      const std::size_t stop = std::min(piece.find_first_of(" \t", k), piece.size());
      s.args.push_back(piece.substr(k, stop - k));
      k = stop;
      while (k < piece.size() && IsSeparator(piece[k])) ++k;
    }
    visit(s);
  }
}

/// A number as both std::from_chars and assimp's fast_atof read it, and as assimp 5.2.5 counts the
/// numbers of a `v` or `vt` line (a word starting with a digit or a sign): an optional sign, a
/// digit, more digits with an optional point and exponent; finite. ".5" is refused: assimp does
/// not count it, reads the line as a vertex of two numbers and drops it.
double Number(const Statement& s, std::string_view arg) {
  const char* first = arg.data() + (arg.front() == '+' ? 1 : 0);
  const char* last = arg.data() + arg.size();
  double x = 0.0;
  const auto r = std::from_chars(first, last, x);
  const bool starts_a_number =
      arg.front() == '-' || arg.front() == '+' || (arg.front() >= '0' && arg.front() <= '9');
  if (!starts_a_number || first == last || *first == '+' || (arg.front() == '+' && *first == '-') ||
      r.ec != std::errc() || r.ptr != last || !std::isfinite(x)) {
    Refuse(s.at + "'" + std::string(s.keyword) + "' holds " + Quote(arg) +
           " where a number belongs (a finite one)");
  }
  return x;
}

void RequireCount(const Statement& s, std::initializer_list<std::size_t> counts,
                  const std::string& expected) {
  for (const std::string_view arg : s.args) Number(s, arg);
  if (std::find(counts.begin(), counts.end(), s.args.size()) == counts.end()) {
    Refuse(s.at + "'" + std::string(s.keyword) + "' with " + Count(s.args.size()) +
           " numbers (expected " + expected + ")");
  }
}

// ---- MTL ----

/// Texture options and how many values follow each (assimp 5.2.5 skips that many; `-bm` it reads
/// as a number).
struct TextureOption {
  std::string_view name;
  std::size_t values;
  bool numbers;
};
constexpr TextureOption kTextureOptions[] = {
    {"-clamp", 1, false},  {"-type", 1, false}, {"-bm", 1, true},      {"-blendu", 1, false},
    {"-blendv", 1, false}, {"-boost", 1, true}, {"-texres", 1, false}, {"-imfchan", 1, false},
    {"-mm", 2, true},      {"-o", 3, true},     {"-s", 3, true},       {"-t", 3, true},
};

void CheckTextureStatement(const Statement& s) {
  std::size_t i = 0;
  while (i < s.args.size() && s.args[i].front() == '-') {
    const auto* option = std::find_if(std::begin(kTextureOptions), std::end(kTextureOptions),
                                      [&](const TextureOption& o) { return o.name == s.args[i]; });
    if (option == std::end(kTextureOptions)) {
      Refuse(s.at + "unknown texture option " + Quote(s.args[i]) +
             " (known: -clamp, -type, -bm, -blendu, -blendv, -boost, -texres, -imfchan, -mm, -o, "
             "-s, -t)");
    }
    if (i + option->values >= s.args.size()) {
      Refuse(s.at + "texture option " + Quote(option->name) + " needs " + Count(option->values) +
             " value(s) and then the file name");
    }
    if (option->numbers) {
      for (std::size_t k = 1; k <= option->values; ++k) Number(s, s.args[i + k]);
    }
    i += 1 + option->values;
  }
  if (i >= s.args.size()) {
    Refuse(s.at + "'" + std::string(s.keyword) + "' without a file name");
  }
}

void CheckMtl(const std::string& name, std::string_view text) {
  bool have_material = false;
  ForEachStatement(
      "MTL file " + name, text, Indent::kAllowedAfterTheFirstLine, [&](const Statement& s) {
        const std::string_view k = s.keyword;
        if (k == "newmtl") {
          if (s.args.empty()) Refuse(s.at + "'newmtl' without a material name");
          have_material = true;
          return;
        }
        if (!have_material) {
          // assimp 5.2.5 writes such a statement through a null material.
          Refuse(s.at + Quote(k) + " before the first 'newmtl'");
        }
        if (IsOneOf(k, {"Ka", "Kd", "Ks", "Ke", "Tf", "Ps"})) {
          RequireCount(s, {1, 3}, "1 or 3");
        } else if (IsOneOf(k, {"d", "Tr", "Ns", "Ni", "Pr", "Pm", "Pc", "Pcr", "sharpness"})) {
          RequireCount(s, {1}, "1");
        } else if (k == "illum") {
          int model = -1;
          const std::string_view v = s.args.size() == 1 ? s.args[0] : std::string_view();
          const auto r = std::from_chars(v.data(), v.data() + v.size(), model);
          if (v.empty() || r.ec != std::errc() || r.ptr != v.data() + v.size() || model < 0 ||
              model > 10) {
            Refuse(s.at + "'illum' takes one whole number from 0 to 10");
          }
        } else if (IsOneOf(k, {"map_Kd", "map_Ka", "map_Ks", "map_Ke", "map_emissive", "map_d",
                               "map_bump", "map_Bump", "bump", "map_Kn", "norm", "refl", "map_disp",
                               "disp", "map_ns", "map_Ns", "map_Pr", "map_Pm", "map_Ps"})) {
          CheckTextureStatement(s);
        } else {
          Refuse(
              s.at + "unknown or unsupported MTL statement " + Quote(k) +
              " (airis reads newmtl, Ka, Kd, Ks, Ke, Tf, Ps, d, Tr, Ns, Ni, Pr, Pm, Pc, Pcr, illum "
              "and texture maps such as map_Kd)");
        }
      });
}

/// `mtllib FILE`: assimp 5.2.5 takes the rest of the line as one name next to the OBJ.
void CheckMaterialLibrary(const Statement& s, const fs::path& obj_path) {
  const std::string_view name = s.rest;
  if (name.empty()) Refuse(s.at + "'mtllib' without a file name");
  if (IsSeparator(name.back())) {
    Refuse(s.at + "'mtllib' file name " + Quote(name) + " ends in white space");
  }
  const std::string folder = obj_path.parent_path().string();
  const fs::path file =
      folder.empty() ? fs::path(name) : fs::path(folder + "/" + std::string(name));
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".mtl") {
    Refuse(s.at + "'mtllib' names " + Quote(name) + ", not a .mtl file");
  }
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    Refuse(s.at + "'mtllib' names " + Quote(name) + ", which is not a file (looked for " +
           file.string() + ")");
  }
  const std::uintmax_t bytes = fs::file_size(file, ec);
  if (ec || bytes > engine::kMaxMeshFileBytes) {
    Refuse(s.at + "'mtllib' names " + Quote(name) + ": unreadable or more than " +
           Count(engine::kMaxMeshFileBytes) + " bytes");
  }
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CheckMtl(std::string(name), text);
}

// ---- OBJ ----

/// The corners of an `f`, `l` or `p` statement: v, v/vt, v//vn or v/vt/vn, one form per statement.
class Corners {
 public:
  /// Elements read so far (v, vt, vn) and the largest positive index of each, with its line.
  std::array<std::int64_t, 3> counts{};
  std::array<std::int64_t, 3> largest{};
  std::array<std::string, 3> largest_at{};

  void Check(const Statement& s) {
    const std::size_t fewest = s.keyword == "f" ? 3 : s.keyword == "l" ? 2 : 1;
    if (s.args.size() < fewest) {
      Refuse(s.at + "'" + std::string(s.keyword) + "' with " + Count(s.args.size()) +
             " corners (at least " + Count(fewest) + ")");
    }
    int first_form = -1;
    for (const std::string_view corner : s.args) {
      std::array<std::string_view, 3> parts{};
      std::size_t n = 0, from = 0;
      for (;;) {
        const std::size_t slash = corner.find('/', from);
        if (n == 3) Bad(s, corner);
        parts[n++] = corner.substr(from, slash == std::string_view::npos ? slash : slash - from);
        if (slash == std::string_view::npos) break;
        from = slash + 1;
      }
      if (parts[0].empty() || (n == 2 && parts[1].empty()) || (n == 3 && parts[2].empty())) {
        Bad(s, corner);
      }
      const int form = static_cast<int>(n) * 2 + (parts[1].empty() ? 1 : 0);
      if (s.keyword == "p" && n > 1) {
        Refuse(s.at + "'p' corner " + Quote(corner) + ": a point names a position (v) only");
      }
      if (first_form < 0) first_form = form;
      if (form != first_form) {
        Refuse(s.at + "'" + std::string(s.keyword) + "' corner " + Quote(corner) +
               " is not of the form of the statement's first corner " + Quote(s.args[0]));
      }
      for (std::size_t kind = 0; kind < n; ++kind) {
        if (!parts[kind].empty()) Index(s, corner, parts[kind], kind);
      }
    }
  }

  void Finish() const {
    static constexpr const char* kKinds[] = {"position (v)", "texture coordinate (vt)",
                                             "normal (vn)"};
    for (std::size_t kind = 0; kind < 3; ++kind) {
      if (largest[kind] > counts[kind]) {
        Refuse(largest_at[kind] + "index " + Count(static_cast<std::uint64_t>(largest[kind])) +
               " names no " + kKinds[kind] + ": the file has " +
               Count(static_cast<std::uint64_t>(counts[kind])));
      }
    }
  }

 private:
  [[noreturn]] static void Bad(const Statement& s, std::string_view corner) {
    Refuse(s.at + "'" + std::string(s.keyword) + "' corner " + Quote(corner) +
           " is not of the form v, v/vt, v//vn or v/vt/vn (indices from 1, or negative)");
  }

  void Index(const Statement& s, std::string_view corner, std::string_view part, std::size_t kind) {
    static constexpr const char* kKinds[] = {"position (v)", "texture coordinate (vt)",
                                             "normal (vn)"};
    std::int64_t index = 0;
    const auto r = std::from_chars(part.data(), part.data() + part.size(), index);
    if (r.ec != std::errc() || r.ptr != part.data() + part.size() || index == 0) Bad(s, corner);
    if (index < 0 && -index > counts[kind]) {
      Refuse(s.at + "index " + Count(static_cast<std::uint64_t>(-index)) +
             " from the end names no " + kKinds[kind] + ": " +
             Count(static_cast<std::uint64_t>(counts[kind])) + " are read before it");
    }
    if (index > largest[kind]) {
      largest[kind] = index;
      largest_at[kind] = s.at;
    }
  }
};

}  // namespace

void CheckObjFile(const std::string& path, const std::string& text) {
  Corners corners;
  std::string coloured_at, plain_at;  // the first vertex with a colour, and without
  ForEachStatement("OBJ", text, Indent::kRefused, [&](const Statement& s) {
    const std::string_view k = s.keyword;
    if (k == "v") {
      RequireCount(s, {3, 4, 6}, "3, 4 or 6: x y z, x y z w, or x y z r g b");
      if (s.args.size() == 4 && Number(s, s.args[3]) == 0.0) {
        Refuse(s.at + "'v' with a weight w of 0 (x/w, y/w, z/w are undefined)");
      }
      std::string& seen = s.args.size() == 6 ? coloured_at : plain_at;
      if (seen.empty()) seen = s.at;
      if (!coloured_at.empty() && !plain_at.empty()) {
        Refuse(s.at + "vertex colours on some vertices only (" + coloured_at + "with; " + plain_at +
               "without): give every vertex a colour or none");
      }
      ++corners.counts[0];
    } else if (k == "vt") {
      RequireCount(s, {2, 3}, "2 or 3");
      ++corners.counts[1];
    } else if (k == "vn") {
      RequireCount(s, {3}, "3");
      ++corners.counts[2];
    } else if (k == "vp") {
      RequireCount(s, {1, 2, 3}, "1 to 3");
    } else if (k == "f" || k == "l" || k == "p") {
      corners.Check(s);
    } else if (k == "usemtl") {
      if (s.args.empty()) Refuse(s.at + "'usemtl' without a material name");
    } else if (k == "mtllib") {
      CheckMaterialLibrary(s, path);
    } else if (!IsOneOf(k, {"o", "g", "s"})) {
      Refuse(s.at + "unknown or unsupported OBJ statement " + Quote(k) +
             " (airis reads v, vt, vn, vp, f, l, p, o, g, s, usemtl, mtllib and # comments)");
    }
  });
  corners.Finish();
}

}  // namespace airis::scenes
