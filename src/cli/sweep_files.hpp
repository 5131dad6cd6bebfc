// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The two files a running `restitution sweep` writes: FILE.partial (every finished row, in completion
// order per worker, for --resume) and the final table, written in grid order into FILE.tmp while the workers
// compute and renamed onto FILE when the last row is in. Writing the table as rows arrive, rather than
// building and writing it once every point is solved, keeps that work off the one thread that runs after the
// solves: on two threads it was the serial part that capped the speed-up (docs/performance.md).
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace restitution::cli {

// Appends finished rows to the partial file. Each worker thread has its own buffer, written with one
// append-mode write(2) of whole lines when it holds 256 KiB or every 100 ms: no lock between the workers, and
// no cache line that moves between the cores per row (a shared stdio buffer written under the sweep's lock
// made two threads spend ~8 % more CPU than one).
class PartialFile {
 public:
  // keep_bytes > 0: resume an existing file, cut to its last complete line; else start it with `preamble`.
  // `writers`: the number of worker threads that append (each with its own number below it).
  PartialFile(const std::filesystem::path& path, std::size_t keep_bytes, const std::string& preamble,
              unsigned writers);
  ~PartialFile();  // what the buffers still hold is written: an interrupted sweep keeps every finished point
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  // Appends "index,row\n" to the writer's buffer; concurrent calls must have different writers. Throws
  // IoError naming the file when a write fails.
  void append(unsigned writer, std::size_t index, const std::string& row);

 private:
  struct alignas(64) Buffer {
    std::string lines;
    long long last_write_ns = 0;  // steady clock
  };
  void write(Buffer& buffer);
  [[noreturn]] void fail(int error) const;
  std::filesystem::path path_;
  int fd_ = -1;
  std::vector<Buffer> buffers_;
};

// The final CSV, written in grid order while rows arrive in any order. Each row has a slot of its own,
// which a worker may fill without a lock; add() (called one at a time, after the slot is filled) writes
// every row that now continues the written prefix and frees it.
class OrderedTable {
 public:
  // Opens target.tmp (the folder exists: the partial file was created in it) and writes the header line.
  OrderedTable(std::filesystem::path target, const std::string& header, std::size_t rows);
  ~OrderedTable();  // not committed (interrupted, failed): the temporary file is removed
  OrderedTable(const OrderedTable&) = delete;
  OrderedTable& operator=(const OrderedTable&) = delete;

  std::string& slot(std::size_t index) { return rows_[index]; }
  // The row in slot(index) is complete.
  void add(std::size_t index);
  // Every row added: flush, close and rename the temporary file onto the target. Throws IoError.
  void commit();

 private:
  [[noreturn]] void fail() const;
  std::filesystem::path target_, temporary_;
  std::FILE* file_ = nullptr;
  std::vector<std::string> rows_;
  std::vector<char> ready_;  // set by add(): slots below next_ are written and freed
  std::size_t next_ = 0;
};

}  // namespace restitution::cli
