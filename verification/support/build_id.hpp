#pragma once
#include <filesystem>
#include <string>

namespace sphv {

// SHA-256 of a file's bytes, as 64 hex digits (OpenSSL's libcrypto). Throws when unreadable.
std::string sha256_of_file(const std::filesystem::path& file);

// SHA-256 of the running executable (/proc/self/exe), computed once. With the build flags it
// names what produced a result: a sweep reuses a point only when both match (see points.cpp).
const std::string& executable_sha256();

}  // namespace sphv
