#include "io_test_support.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tridem::test {

Snapshot sample_snapshot() {
  Snapshot s;
  s.step = 1200;
  s.time = 0.012000000000000002;
  s.resize(3);
  const double vertices[3][6] = {{0, 0, 1, 0, 0, 1},
                                 {1.5, 0, 2.5, 0, 2.0, 0.9},
                                 {-1, -1, 3, -1, 1, -0.2}};
  for (std::size_t k = 0; k < 3; ++k) {
    const double* v = vertices[k];
    s.x1[k] = v[0], s.y1[k] = v[1], s.x2[k] = v[2], s.y2[k] = v[3], s.x3[k] = v[4],
    s.y3[k] = v[5];
    s.x[k] = (v[0] + v[2] + v[4]) / 3;
    s.y[k] = (v[1] + v[3] + v[5]) / 3;
  }
  s.theta = {0.1, -2.0 / 3.0, 0};
  s.vx = {0.1, 2.5, 0};
  s.vy = {-1.0 / 3.0, 1e-300, 0};
  s.omega = {3.14159265358979, -7.25, 0};
  s.fx = {12.5, -3.0, -9.5};
  s.fy = {1.0 / 7.0, 42.0, -143.0 / 7.0};
  s.torque = {0.5, -0.125, 6.75};
  s.mass = {500, 450, 4000};
  s.inertia = {83.3, 60.1, 5000};
  s.material = {0, 1, 0};
  s.motion = {Motion::Free, Motion::Free, Motion::Fixed};
  // Normals (0.6, 0.8) and (0, -1): unit vectors; the first slides.
  s.contacts = {{0, 1, -3.0, 2.0, 1.2, 0.3, 0.6, 0.8, true, 0.0125},
                {0, 2, 0.25, 20.0 / 3.0, 0.4, -0.05, 0.0, -1.0, false, 1.0 / 3.0}};
  return s;
}

TempDir::TempDir() {
  std::string name = (std::filesystem::temp_directory_path() / "tridem-io-XXXXXX").string();
  if (!mkdtemp(name.data())) throw std::runtime_error("mkdtemp failed");
  path_ = name;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::map<std::string, std::string> files_under(const std::filesystem::path& dir,
                                               const std::string& skip_extension) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file() && (skip_extension.empty() || e.path().extension() != skip_extension))
      files[std::filesystem::relative(e.path(), dir).string()] = read_file(e.path());
  return files;
}

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> read_lines(const std::filesystem::path& file) {
  std::istringstream in(read_file(file));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

std::vector<double> numbers(const std::string& row) {
  std::vector<double> out;
  for (const std::string& cell : cells(row)) out.push_back(std::strtod(cell.c_str(), nullptr));
  return out;
}

}  // namespace tridem::test
