#pragma once
// How a failure reaches the user: one line "contessa: error: ..." on stderr and an exit status (2 bad
// input, 1 anything else), on any number of ranks, never a hang, an MPI abort trace or a backtrace.
//
// The rule for ranks: bad input found before the run starts is agreed on collectively (agreeOnInput);
// after that, an InputError must be thrown on every rank alike (it comes from data every rank shares).
// Errors that only some ranks see during the run (a failed allocation, a write error) are caught by
// reportFailures, which lets the failing ranks leave without waiting for the others.
#include <functional>
#include <memory>
#include <string>

#include <Teuchos_Comm.hpp>

namespace contessa::app {

/// Runs `body` (the program once MPI is up) and returns its exit status; an exception becomes one
/// line on stderr and status 2 (InputError) or 1 (anything else; std::bad_alloc as "out of memory
/// while <activity>"). Create it on every rank right after MPI starts (it duplicates the
/// communicator, a collective call).
class FailureReporter {
 public:
  FailureReporter(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::string activity);
  ~FailureReporter();
  int run(const std::function<int()>& body);

 private:
  int fail(const std::string& message, int status);
  struct Agreement;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::unique_ptr<Agreement> agreement_;
  std::string activity_;
};

/// Runs `validate` on every rank, then the ranks agree: when it threw on any rank (a file only some
/// ranks can read), every rank throws the error of the lowest failing rank, so that one line is
/// printed and no rank waits for another in a collective call. `validate` must make no collective call.
void agreeOnInput(const Teuchos::Comm<int>& comm, const std::function<void()>& validate);

/// The deck file's text, read on rank 0 only and sent to every rank (a named pipe can be read once).
/// Throws InputError on every rank when rank 0 cannot read it.
std::string shareDeckText(const Teuchos::Comm<int>& comm, const std::string& path);

}  // namespace contessa::app
