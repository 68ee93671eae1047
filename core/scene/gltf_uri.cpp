#include "core/scene/gltf_uri.hpp"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include "core/scene/input_file.hpp"

namespace pbr {

namespace fs = std::filesystem;

namespace {

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// RFC 3986 percent-decoding. A malformed escape is an error rather than kept literally, and a NUL byte would cut
// the path short at the C library, so neither can name a different file than the one the URI spells.
std::string percentDecode(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    const int hi = i + 2 < uri.size() ? hexDigit(uri[i + 1]) : -1, lo = hi >= 0 ? hexDigit(uri[i + 2]) : -1;
    if (lo < 0) throw std::runtime_error(quoteUri(uri) + ": bad percent-encoding");
    const char c = static_cast<char>(hi * 16 + lo);
    if (c == '\0') throw std::runtime_error(quoteUri(uri) + ": encodes a NUL byte");
    out += c;
    i += 2;
  }
  return out;
}

// True when `path` is `folder` or below it, after following symbolic links in both.
bool inside(const fs::path& path, const fs::path& folder) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(path, ec);
  if (ec) return false;
  const fs::path f = fs::weakly_canonical(folder, ec);
  if (ec) return false;
  return std::mismatch(f.begin(), f.end(), p.begin(), p.end()).first == f.end();
}

}  // namespace

bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

std::string quoteUri(const std::string& uri) {
  if (isDataUri(uri)) {
    const std::size_t comma = uri.find(',');
    return "'" + uri.substr(0, std::min<std::size_t>(comma == std::string::npos ? uri.size() : comma + 1, 40)) + "...'";
  }
  return "'" + (uri.size() <= 60 ? uri : uri.substr(0, 57) + "...") + "'";
}

std::size_t dataUriSize(const std::string& uri) {
  const std::size_t comma = uri.find(',');
  if (comma == std::string::npos || comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0) {
    throw std::runtime_error(quoteUri(uri) + ": only base64 data: URIs are supported");
  }
  std::size_t length = uri.size() - comma - 1, padding = 0;
  while (padding < 2 && padding < length && uri[uri.size() - 1 - padding] == '=') ++padding;
  if (length % 4 != 0) {
    throw std::runtime_error(quoteUri(uri) + ": base64 data is not a whole number of 4-character groups");
  }
  return length / 4 * 3 - padding;
}

fs::path placeGltfUri(const std::string& uri, const fs::path& folder, const UriPolicy& policy) {
  if (uri.empty()) throw std::runtime_error("empty URI");
  if (uri.find("://") != std::string::npos) {
    throw std::runtime_error(quoteUri(uri) + ": only file paths and data: URIs are supported");
  }
  const std::string decoded = percentDecode(uri);
  const fs::path relative(decoded);
  const fs::path path = (relative.is_absolute() ? relative : folder / relative).lexically_normal();
  if (!policy.allowOutside && !inside(path, folder.empty() ? fs::path(".") : folder)) {
    throw std::runtime_error(quoteUri(uri) + " leaves the model's folder (--allow-outside-uris allows it)");
  }
  return path;
}

fs::path resolveGltfUri(const std::string& uri, const fs::path& folder, const UriPolicy& policy) {
  const fs::path path = placeGltfUri(uri, folder, policy);
  try {
    requireRegularFile(path.string());
  } catch (const std::runtime_error& e) {
    // The file's own message, with the URI as the file spells it.
    const std::string what = e.what(), prefix = path.string() + ": ";
    throw std::runtime_error(quoteUri(uri) + ": " + (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what));
  }
  return path;
}

}  // namespace pbr
