// SPDX-License-Identifier: BSD-3-Clause
// A line-oriented probe of genmros' headers, for peers in other languages.
// Reads commands on stdin, answers one line each:
//   sample TYPE SEED   ->  HEX              (wire image of a text-mode instance)
//   reencode TYPE HEX  ->  CONSUMED HEX     (deserialize, then serialize again)
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "harness_random.h"
#include "harness_sides.h"

static std::string to_hex(const std::vector<uint8_t>& bytes) {
  static const char digits[] = "0123456789abcdef";
  std::string hex;
  for (uint8_t byte : bytes) {
    hex += digits[byte >> 4];
    hex += digits[byte & 15];
  }
  return hex.empty() ? "-" : hex;
}

static std::vector<uint8_t> from_hex(const std::string& hex) {
  std::vector<uint8_t> bytes;
  for (size_t i = 0; hex != "-" && i + 1 < hex.size(); i += 2) {
    bytes.push_back(static_cast<uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  }
  return bytes;
}

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream words(line);
    std::string command;
    int type = 0;
    words >> command >> type;
    if (command == "sample") {
      unsigned long long seed = 0;
      words >> seed;
      std::cout << to_hex(mros_side::sample(type, seed, harness::kText)) << std::endl;
    } else if (command == "reencode") {
      std::string hex;
      words >> hex;
      const std::vector<uint8_t> input = from_hex(hex);
      std::vector<uint8_t> output;
      const int32_t consumed = mros_side::reencode(type, input.data(), static_cast<uint32_t>(input.size()), output);
      std::cout << consumed << ' ' << to_hex(output) << std::endl;
    } else {
      std::cout << "unknown command" << std::endl;
    }
  }
  return 0;
}
