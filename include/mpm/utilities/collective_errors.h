#pragma once

#include <deal.II/base/mpi.h>

#include <mpm/utilities/input_error.h>

#include <exception>
#include <string>
#include <utility>

/**
 * Errors found on some ranks reported on all of them. A rank that throws
 * alone leaves the others waiting in the next collective call; so each
 * rank records what went wrong, and at a collective point every rank
 * throws the same exception with the message of the lowest failing rank.
 */
namespace mpm
{
  /// The first problem a rank met (later ones are usually its
  /// consequences).
  class FirstProblem
  {
  public:
    /// Keep @p problem unless one is kept already; "" is no problem.
    void
    record(const std::string &problem)
    {
      if (message.empty())
        message = problem;
    }

    bool
    empty() const
    {
      return message.empty();
    }

    const std::string &
    text() const
    {
      return message;
    }

    void
    clear()
    {
      message.clear();
    }

  private:
    std::string message;
  };

  /// Collective: if any rank has a problem, throw Error(prefix + the
  /// lowest failing rank's message) on every rank.
  template <typename Error>
  void
  throw_if_any(const MPI_Comm     comm,
               const std::string &prefix,
               const std::string &local_problem)
  {
    const unsigned int rank   = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int nranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first =
      dealii::Utilities::MPI::min(local_problem.empty() ? nranks : rank, comm);
    if (first < nranks)
      throw Error(
        prefix + dealii::Utilities::MPI::broadcast(comm, local_problem, first));
  }

  /// Run @p work; what it throws becomes the returned message ("" if
  /// nothing).
  template <typename Work>
  std::string
  problem_of(Work &&work)
  {
    try
      {
        std::forward<Work>(work)();
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return {};
  }

  /// Collective: run @p work on rank 0 only (files that one rank writes);
  /// whatever it throws is thrown as Error(prefix + message) on every rank.
  template <typename Error, typename Work>
  void
  on_root(const MPI_Comm comm, const std::string &prefix, Work &&work)
  {
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      problem = problem_of(std::forward<Work>(work));
    throw_if_any<Error>(comm, prefix, problem);
  }
} // namespace mpm
