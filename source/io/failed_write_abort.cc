#include <mpm/io/failed_write_abort.h>

#include <algorithm>
#include <cstring>

#include <signal.h>
#include <unistd.h>

namespace mpm
{
  namespace
  {
    // The handler may only use what is safe in a signal handler: the
    // message is formatted before the write starts.
    char             text[4096];
    std::size_t      length = 0;
    struct sigaction previous;

    extern "C" void
    report_and_exit(int)
    {
      std::size_t done = 0;
      while (done < length)
        {
          const ssize_t n = ::write(STDERR_FILENO, text + done, length - done);
          if (n <= 0)
            break;
          done += static_cast<std::size_t>(n);
        }
      _exit(2);
    }
  } // namespace

  FailedWriteAbort::FailedWriteAbort(const std::string &message)
  {
    length = std::min(message.size(), sizeof(text) - 1);
    std::memcpy(text, message.data(), length);
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = report_and_exit;
    sigemptyset(&action.sa_mask);
    sigaction(SIGABRT, &action, &previous);
  }

  FailedWriteAbort::~FailedWriteAbort()
  {
    sigaction(SIGABRT, &previous, nullptr);
  }
} // namespace mpm
