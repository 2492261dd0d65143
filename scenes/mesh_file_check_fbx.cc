#include "scenes/mesh_file_check_fbx.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string_view>
#include <vector>

#include "scenes/mesh_loader.h"

namespace airis::scenes {

namespace {

[[noreturn]] void Refuse(const std::string& problem) { throw MeshLoadError(problem); }

std::string ReadBytes(const std::string& path, std::uintmax_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string out(count, '\0');
  in.read(out.data(), static_cast<std::streamsize>(count));
  out.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return out;
}

// Scopes of real files are a few levels deep; assimp's parser recurses once per level.
constexpr int kMaxFbxDepth = 64;

enum class Kind { kData, kKey, kOpen, kClose, kComma };

struct Token {
  Kind kind;
  std::size_t line;         // where it starts
  std::size_t assimp_line;  // as assimp counts it: a value ended by a line end is on the next
};

bool IsLineEnd(char c) { return c == '\r' || c == '\n' || c == '\0' || c == '\f'; }
bool IsSpaceOrLineEnd(char c) { return c == ' ' || c == '\t' || IsLineEnd(c); }

/// The tokens of an ASCII FBX file as assimp 5.2.5's tokenizer makes them (FBXTokenizer.cpp:
/// reading stops at a NUL byte; an unfinished value at the end is dropped), refusing the two
/// inputs where it stops with an error.
std::vector<Token> Tokenize(std::string_view text) {
  std::vector<Token> tokens;
  std::size_t line = 1;
  std::size_t token_line = 0;
  bool comment = false, quoted = false, pending = false, in_token = false;
  const auto where = [&] { return "ASCII FBX line " + std::to_string(line) + ": "; };
  const auto end_token = [&](Kind kind) {
    if (in_token) tokens.push_back({kind, token_line, line});
    in_token = false;
  };
  for (const char c : text) {
    if (c == '\0') break;
    if (IsLineEnd(c)) {
      comment = false;
      ++line;
    }
    if (comment) continue;
    if (quoted) {
      if (c == '"') {
        quoted = false;
        end_token(Kind::kData);
        pending = false;
      }
      continue;
    }
    switch (c) {
      case '"':
        if (in_token) Refuse(where() + "a '\"' inside a value");
        in_token = true;
        token_line = line;
        quoted = true;
        continue;
      case ';':
        end_token(Kind::kData);
        comment = true;
        continue;
      case '{':
        end_token(Kind::kData);
        tokens.push_back({Kind::kOpen, line, line});
        continue;
      case '}':
        end_token(Kind::kData);
        tokens.push_back({Kind::kClose, line, line});
        continue;
      case ',':
        // After a value ended by '{' or '}' on the same line, assimp still expects one here.
        if (pending && !in_token) Refuse(where() + "a ',' right after '{' or '}'");
        if (pending) end_token(Kind::kData);
        tokens.push_back({Kind::kComma, line, line});
        continue;
      case ':':
        if (!pending) Refuse(where() + "a ':' without a key name before it");
        if (!in_token) Refuse(where() + "a ':' right after '{' or '}'");
        end_token(Kind::kKey);
        continue;
      default:
        break;
    }
    if (IsSpaceOrLineEnd(c)) {
      end_token(Kind::kData);
      pending = false;
    } else {
      if (!in_token) token_line = line;
      in_token = true;
      pending = true;
    }
  }
  return tokens;
}

/// assimp 5.2.5's FBX parser (FBXParser.cpp: Scope and Element), refusing where it throws.
class Parser {
 public:
  explicit Parser(const std::vector<Token>& tokens) : tokens_(tokens) {}

  void Scope(bool top, int depth) {
    if (depth > kMaxFbxDepth) {
      Fail("scopes nested more than " + std::to_string(kMaxFbxDepth) + " deep", current_);
    }
    const Token* n = Advance();
    if (n == nullptr) Fail("no element (the file holds no key)", last_);
    while (n->kind != Kind::kClose) {
      if (n->kind != Kind::kKey) Fail("expected a key (a name and ':')", n);
      Element(depth);
      n = current_;
      if (n == nullptr) {
        if (top) return;
        Fail("the file ends inside '{'", last_);
      }
    }
  }

 private:
  void Element(int depth) {
    const Token* n = nullptr;
    do {
      n = Advance();
      if (n == nullptr) Fail("the file ends inside an element (expected a value or '}')", last_);
      if (n->kind == Kind::kData) {
        const Token* prev = n;
        n = Advance();
        if (n == nullptr)
          Fail("the file ends after a value (expected '{', '}', ',' or a key)", last_);
        // A value on the next line continues the list.
        if (n->kind == Kind::kData && n->assimp_line == prev->assimp_line + 1) continue;
        if (n->kind == Kind::kData) Fail("a value where '{', '}', ',' or a key belongs", n);
      }
      if (n->kind == Kind::kOpen) {
        Scope(false, depth + 1);
        if (current_ == nullptr || current_->kind != Kind::kClose) Fail("expected '}'", last_);
        Advance();
        return;
      }
    } while (n->kind != Kind::kKey && n->kind != Kind::kClose);
  }

  const Token* Advance() {
    last_ = current_;
    current_ = next_ < tokens_.size() ? &tokens_[next_++] : nullptr;
    return current_;
  }

  [[noreturn]] static void Fail(const std::string& problem, const Token* at) {
    Refuse("ASCII FBX line " + std::to_string(at != nullptr ? at->line : 1) + ": " + problem);
  }

  const std::vector<Token>& tokens_;
  std::size_t next_ = 0;
  const Token* current_ = nullptr;
  const Token* last_ = nullptr;
};

}  // namespace

void CheckFbx(const std::string& path, std::uintmax_t file_bytes) {
  static constexpr std::string_view kBinaryMagic("Kaydara FBX Binary  \0", 21);
  static constexpr std::string_view kFirstRecord = "FBXHeaderExtension:";
  const std::string text = ReadBytes(path, file_bytes);
  if (text.compare(0, kBinaryMagic.size(), kBinaryMagic) == 0) return;
  std::size_t at = 0;
  while (at < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[at]))) {
      ++at;
    } else if (text[at] == ';') {
      at = std::min(text.find('\n', at), text.size());
    } else {
      break;
    }
  }
  if (text.compare(at, kFirstRecord.size(), kFirstRecord) != 0) {
    Refuse("not an FBX file: neither the binary FBX magic nor an ASCII FBX starting with '" +
           std::string(kFirstRecord) + "'");
  }
  Parser(Tokenize(text)).Scope(true, 0);
}

}  // namespace airis::scenes
