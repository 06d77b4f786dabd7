#pragma once
// Seeded generator of malformed inputs for the parsers a user reaches (--set values, level
// lists, input files). The same seed gives the same sequence on the same standard library, so a
// failing input is replayed from the seed and index the test prints.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace sphv::fuzz {

// The seed every fuzz test starts from (a failure prints it with the input's index).
inline constexpr std::uint64_t seed = 20261130;

// The whole content of file f (empty if it cannot be read): what a run wrote, or a valid file to mutate.
inline std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

class Inputs {
 public:
  explicit Inputs(std::uint64_t seed) : rng_(seed) {}

  // A mutation of a valid text: 1 to 4 edits (a byte replaced, inserted or deleted, an awkward
  // token spliced in, a piece repeated, the text cut short), or an awkward token or random
  // bytes in place of the whole.
  std::string mutate(const std::string& valid) {
    const auto r = below(20);
    if (r == 0) return token();
    if (r == 1) return bytes(below(40));
    std::string s = valid;
    for (auto edits = 1 + below(4); edits > 0; --edits) {
      const std::size_t at = below(s.size() + 1);
      switch (below(7)) {
        case 0: if (at < s.size()) s[at] = byte(); else s += byte(); break;
        case 1: s.insert(at, 1, byte()); break;
        case 2: if (at < s.size()) s.erase(at, 1 + below(3)); break;
        case 3: s.insert(at, token()); break;
        case 4: s.insert(at, s.substr(at, 1 + below(8))); break;
        case 5: s.resize(at); break;
        default: s = token() + s + token(); break;
      }
    }
    return s;
  }

  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng_() % n); }

 private:
  char byte() {
    static const std::string usual = "0123456789+-.,eE=x \t\nnaifNAIF";
    return below(3) ? usual[below(usual.size())] : static_cast<char>(rng_() & 0xff);
  }
  std::string bytes(std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += static_cast<char>(rng_() & 0xff);
    return s;
  }
  std::string token() {
    static const std::vector<std::string> tokens = {
        "", " ", "nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e999", "-1e999", "1e-999", "4.9e-324",
        "1.7976931348623157e308", "0x1p3", "0x10", "+1", "-0", "0", "-1", "0.0", "9223372036854775807",
        "9223372036854775808", "-9223372036854775809", "99999999999999999999999999", "1.", ".", "e", "1e",
        "1e+", "--", "-", ",", ",,", "=", "==", "\t", "\n", "\r\n", std::string(1, '\0'), "\xff\xfe",
        "\xc3\xa9", "\xef\xbc\x91", "%s%n", "${HOME}", "'", "\"", "\\", "1,2", "1;2", "16,,32", ",16",
        "16,", "true", "null", "[1]", "{}", std::string(300, '9'), std::string(2000, 'x')};
    return tokens[below(tokens.size())];
  }
  std::mt19937_64 rng_;
};

}  // namespace sphv::fuzz
