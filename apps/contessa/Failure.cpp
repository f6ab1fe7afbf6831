#include "Failure.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <thread>

#include <mpi.h>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include "common/Error.hpp"
#include "common/ErrorText.hpp"
#include "common/MpiCommOf.hpp"
#include "common/RankAgreement.hpp"
#include "deck/DeckReader.hpp"

namespace contessa::app {
namespace {

// How long failing ranks wait for the others to fail too before they leave on their own. Ranks that
// fail alike (bad input after validation) arrive within milliseconds of each other.
constexpr auto kAgreementDeadline = std::chrono::seconds(3);

void printError(const std::string& message) {
  std::fflush(stdout);
  std::fprintf(stderr, "contessa: error: %s\n", message.c_str());
  std::fflush(stderr);
}

void broadcastString(const Teuchos::Comm<int>& comm, int root, std::string& text) {
  int length = static_cast<int>(text.size());
  Teuchos::broadcast(comm, root, &length);
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(comm, root, length, &text[0]);
}

}  // namespace

// The failing ranks agree on a communicator of their own (a duplicate of the run's), so that the
// agreement cannot be mistaken for a collective call of the run that other ranks are waiting in.
struct FailureReporter::Agreement {
  MPI_Comm comm = MPI_COMM_NULL;
};

FailureReporter::FailureReporter(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::string activity)
    : comm_(std::move(comm)), agreement_(std::make_unique<Agreement>()), activity_(std::move(activity)) {
  if (comm_->getSize() == 1) return;
  const auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm_, true);
  MPI_Comm_dup(*mpi->getRawMpiComm(), &agreement_->comm);
}

FailureReporter::~FailureReporter() {
  if (agreement_->comm != MPI_COMM_NULL) MPI_Comm_free(&agreement_->comm);
}

int FailureReporter::run(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    return fail(e.what(), 2);
  } catch (const std::bad_alloc&) {
    return fail("out of memory while " + activity_, 1);
  } catch (const std::exception& e) {
    return fail(plainMessage(e), 1);
  } catch (...) {
    return fail("internal error (an exception of unknown type) while " + activity_, 1);
  }
}

int FailureReporter::fail(const std::string& message, int status) {
  if (comm_->getSize() == 1) {
    printError(message);
    return status;
  }
  // Every failing rank offers (its rank, its status); the lowest rank's line is printed once when all
  // ranks fail. When some ranks do not come (they still run, or wait in a collective call for this
  // one), the failing ranks print their line and leave without MPI_Finalize, which would wait for
  // them: mpiexec then ends the job with the failing rank's status.
  int mine[2] = {comm_->getRank(), status};
  int lowest[2] = {0, 0};
  MPI_Request request;
  MPI_Iallreduce(mine, lowest, 1, MPI_2INT, MPI_MINLOC, agreement_->comm, &request);
  const auto deadline = std::chrono::steady_clock::now() + kAgreementDeadline;
  int done = 0;
  while (MPI_Test(&request, &done, MPI_STATUS_IGNORE) == MPI_SUCCESS && !done &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (done) {
    if (lowest[0] == comm_->getRank()) printError(message);
    return lowest[1];
  }
  printError(message);
  std::_Exit(status);
}

void agreeOnInput(const Teuchos::Comm<int>& comm, const std::function<void()>& validate) {
  std::string message;
  int status = 0;
  try {
    validate();
  } catch (const InputError& e) {
    message = e.what();
    status = 2;
  } catch (const std::bad_alloc&) {
    message = "out of memory while reading the deck and building the mesh";
    status = 1;
  } catch (const std::exception& e) {
    message = plainMessage(e);
    status = 1;
  }
  const RankMessage lowest = lowestSpeakingRank(mpiCommOf(comm), status, std::move(message));
  if (!lowest.spoken()) return;
  message = lowest.message;
  if (lowest.rank != 0) message += " (on rank " + std::to_string(lowest.rank) + ")";
  if (lowest.status == 2) throw InputError(message);
  throw std::runtime_error(message);
}

std::string shareDeckText(const Teuchos::Comm<int>& comm, const std::string& path) {
  std::string text;
  int failed = 0;
  if (comm.getRank() == 0) {
    try {
      text = deck::readDeckText(path);
    } catch (const InputError& e) {
      text = e.what();
      failed = 1;
    }
  }
  Teuchos::broadcast(comm, 0, &failed);
  broadcastString(comm, 0, text);
  if (failed) throw InputError(text);
  return text;
}

}  // namespace contessa::app
