#pragma once

#include <string>

namespace mpm
{
  /// Write @p content to @p file_name via a temporary file and a rename, so
  /// that a reader (or a run killed meanwhile) sees the old or the new
  /// content, both complete. @p durable: the temporary file is flushed to
  /// the storage device before the rename and the folder after it, so
  /// that this also holds for a crash of the machine (checkpoints).
  void
  write_file_atomically(const std::string &file_name,
                        const std::string &content,
                        const bool         durable = false);

  /// fsync the file or folder @p path (its data, or its entries), so that
  /// it survives a crash of the machine, not only of the process.
  void
  flush_to_storage(const std::string &path);
} // namespace mpm
