// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The two files a running sweep_to_file (`restitution sweep`) writes: FILE.partial (every finished row, in
// completion order per worker, for --resume; format in sweep_partial.hpp) and the final table, written in
// grid order into FILE.<random>.tmp (files/temporary_file.hpp) while the workers compute and renamed onto
// FILE when the last row is in. Writing the table as rows arrive, rather than building and writing it once
// every point is solved, keeps that work off the one thread that runs after the solves: on two threads it was
// the serial part that capped the speed-up (docs/performance.md).
//
// A failed write is the last write to its file: the lines a buffer held when its write(2) failed (short or
// refused) are dropped, and nothing is appended after them later, not even by a destructor once space was
// freed (which once put duplicated rows after a cut-off line). What is on disk before the failure stays
// valid.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "sweep/line_reader.hpp"

namespace restitution {

// Appends finished rows to the partial file. Each worker thread has its own buffer, written with one
// append-mode write(2) of whole lines when it holds 256 KiB or every 100 ms: no lock between the workers per
// row, and no cache line that moves between the cores per row (a shared stdio buffer written under the
// sweep's lock made two threads spend ~8 % more CPU than one). The writes themselves take a lock, so that no
// write follows a failed one.
class PartialFile {
 public:
  // keep_bytes > 0: resume an existing file, cut to its last complete line; else start it with `preamble`.
  // `writers`: the number of worker threads that append (each with its own number below it). `option`
  // begins the message of a failed write ("--out"; empty: nothing).
  PartialFile(const std::filesystem::path& path, std::uint64_t keep_bytes, const std::string& preamble,
              unsigned writers, const std::string& option = "");
  // What the buffers still hold is written (an interrupted sweep keeps every finished point), unless a write
  // to the file has failed.
  ~PartialFile();
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  // Appends the row's line to the writer's buffer; concurrent calls must have different writers. Throws
  // IoError naming the file when a write fails, and on every call after that.
  void append(unsigned writer, std::size_t index, const std::string& row);

 private:
  struct alignas(64) Buffer {
    std::string lines;
    long long last_write_ns = 0;  // steady clock
  };
  void write(Buffer& buffer);
  [[noreturn]] void fail(int error) const;
  std::filesystem::path path_;
  std::string failure_prefix_;
  int fd_ = -1;
  std::vector<Buffer> buffers_;
  std::mutex write_mutex_;     // one write(2) at a time, none after a failure
  std::atomic<int> error_{0};  // errno of the failed write, 0: none
};

// The final CSV, written in grid order while rows arrive in any order. It holds only the rows that arrived
// before an earlier one (a reorder buffer of a few rows per worker), and copies the rows that a resumed sweep
// found in FILE.partial from that file when their turn comes: memory stays bounded whatever the grid's size.
class OrderedTable {
 public:
  // Opens target.tmp and writes the header line, then the rows of `done` that begin the table.
  // `done_offsets`: empty, or per grid point the offset of its line in `partial` (PartialSweep::row_offset).
  OrderedTable(std::filesystem::path target, const std::string& header, std::size_t rows,
               std::vector<std::uint64_t> done_offsets, const std::filesystem::path& partial);
  ~OrderedTable();  // not committed (interrupted, failed): the temporary file is removed
  OrderedTable(const OrderedTable&) = delete;
  OrderedTable& operator=(const OrderedTable&) = delete;

  // The point's row is finished (called one at a time): writes every row that now continues the table.
  void add(std::size_t index, std::string row);
  // Every row added: flush, close and rename the temporary file onto the target. Throws IoError.
  void commit();

 private:
  [[nodiscard]] bool done_before(std::size_t index) const;
  void advance();
  void put(std::string_view row);
  void flush();
  [[noreturn]] void fail(int error);
  std::filesystem::path target_, temporary_;
  int fd_ = -1;
  int error_ = 0;  // errno of a failed write: nothing is written after it
  std::string buffer_;
  std::size_t rows_ = 0;
  std::size_t next_ = 0;                        // rows below it are written
  std::map<std::size_t, std::string> waiting_;  // finished rows after a gap
  std::vector<std::uint64_t> done_offsets_;
  std::unique_ptr<FileLines> partial_;  // open while done rows remain to be copied
};

}  // namespace restitution
