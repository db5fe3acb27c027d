#pragma once
// A ParaView collection (.pvd) listing time steps. It is rewritten whole after every
// frame by write_file_atomically (atomic_file.hpp), so a reader, a run that dies or a
// power cut never leaves it half written.
#include <filesystem>
#include <string>
#include <vector>

namespace tridem::io {

class PvdCollection {
 public:
  /// `file` is the .pvd; data set paths are stored relative to its folder.
  explicit PvdCollection(std::filesystem::path file);

  /// Takes over the entries of an existing file with time <= `max_time` (a restarted run
  /// continues its collection); none if there is no file.
  void restore(double max_time);

  /// Lists `dataset` at `time` and rewrites the file. Adding the same data set again
  /// (a step written twice) updates its entry instead of duplicating it.
  void add(double time, const std::filesystem::path& dataset);

  const std::filesystem::path& file() const { return file_; }

 private:
  struct Entry {
    double time;
    std::string file;
  };
  void rewrite() const;

  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

}  // namespace tridem::io
