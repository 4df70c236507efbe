// What both C++ peers share with `benches/examples/peer_ops/`: reading the one input file,
// the timer (the median of PASSES passes over the N operands, ns per operand) and writing the
// `.times` and `.out` files, whose formats that file documents.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace peer {

constexpr std::size_t N = 10000;
constexpr int PASSES = 41;

// Sections of the input file, in file order, with the f64 values per operand.
inline const std::vector<std::pair<std::string, std::size_t>> &sections() {
  static const std::vector<std::pair<std::string, std::size_t>> s = {
      {"pga.motor_a", 8},     {"pga.motor_b", 8},     {"pga.point", 4},    {"pga.rotor_a", 4},
      {"pga.rotor_b", 4},     {"pga.line", 6},        {"cga.vector_a", 5}, {"cga.vector_b", 5},
      {"cga.bivector_a", 10}, {"cga.bivector_b", 10}, {"cga.motor_a", 8},  {"cga.motor_b", 8},
      {"cga.point", 4},       {"cga.ik_angles", 5},  {"cga.blade2_a", 10},
      {"cga.blade2_b", 10},   {"cga.blade4_a", 5},    {"cga.blade0_a", 1}, {"cga.blade0_b", 1},
      {"cga.blade1_a", 5},    {"cga.blade1_b", 5},    {"cga.blade3_a", 10}, {"cga.blade3_b", 10},
      {"cga.blade4_b", 5},    {"cga.blade5_a", 1},    {"cga.blade5_b", 1}};
  return s;
}

using Input = std::map<std::string, std::vector<double>>;

inline Input read_input(const char *path) {
  FILE *f = std::fopen(path, "rb");
  char magic[8];
  std::uint64_t n = 0;
  if (!f || std::fread(magic, 1, 8, f) != 8 || std::memcmp(magic, "GAPEERS1", 8) != 0 ||
      std::fread(&n, 8, 1, f) != 1 || n != N) {
    std::fprintf(stderr, "%s: not a peer input file of %zu operands\n", path, N);
    std::exit(1);
  }
  Input in;
  for (auto &[name, width] : sections()) {
    std::vector<double> v(N * width);
    if (std::fread(v.data(), 8, v.size(), f) != v.size()) {
      std::fprintf(stderr, "%s: short section %s\n", path, name.c_str());
      std::exit(1);
    }
    in[name] = std::move(v);
  }
  std::fclose(f);
  return in;
}

// Keeps the compiler from dropping or merging passes: the memory behind `p` is observed.
inline void clobber(const void *p) { asm volatile("" : : "g"(p) : "memory"); }

// The median over PASSES of one pass (after 3 warm-up passes), in ns per operand.
template <class F> double time_pass(F &&pass) {
  for (int i = 0; i < 3; ++i) pass();
  std::vector<double> t;
  for (int i = 0; i < PASSES; ++i) {
    auto a = std::chrono::steady_clock::now();
    pass();
    auto b = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::nano>(b - a).count() / N);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// Timings and outputs (our blade order, f64) of one run, written as `PREFIX.times` and `.out`.
struct Record {
  std::vector<std::pair<std::string, double>> times;
  std::vector<std::pair<std::string, std::vector<double>>> outputs;

  void add(const std::string &key, double ns, std::vector<double> out) {
    times.emplace_back(key, ns);
    outputs.emplace_back(key, std::move(out));
  }

  void write(const std::string &prefix) const {
    FILE *t = std::fopen((prefix + ".times").c_str(), "w");
    FILE *o = std::fopen((prefix + ".out").c_str(), "wb");
    if (!t || !o) {
      std::fprintf(stderr, "cannot write %s.times / .out\n", prefix.c_str());
      std::exit(1);
    }
    for (auto &[k, ns] : times) std::fprintf(t, "%s %.4f\n", k.c_str(), ns);
    for (auto &[k, v] : outputs) {
      std::uint32_t len = k.size();
      std::uint64_t count = v.size();
      std::fwrite(&len, 4, 1, o);
      std::fwrite(k.data(), 1, len, o);
      std::fwrite(&count, 8, 1, o);
      std::fwrite(v.data(), 8, v.size(), o);
    }
    std::fclose(t);
    std::fclose(o);
  }
};

}  // namespace peer
