#pragma once

#include <string>

namespace mpm
{
  /**
   * p4est ends the process with abort() when one of its own writes fails
   * (a disk that filled after the free-space check before a checkpoint, or
   * that ran out of file entries). While a guard lives, such an abort
   * prints @p message on the error stream and ends the process with status
   * 2, as every other failed write does, instead of a core dump. The
   * checkpoint being written is then incomplete and never committed, so
   * the latest one stays the one to resume from.
   *
   * One guard at a time; it restores the previous SIGABRT handler when it
   * goes.
   */
  class FailedWriteAbort
  {
  public:
    explicit FailedWriteAbort(const std::string &message);
    ~FailedWriteAbort();
    FailedWriteAbort(const FailedWriteAbort &) = delete;
    FailedWriteAbort &
    operator=(const FailedWriteAbort &) = delete;
  };
} // namespace mpm
