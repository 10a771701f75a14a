#include "study/study_mpi.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#ifdef PROXSIM_HAVE_MPI
#include <mpi.h>
#endif

namespace proxsim {

namespace {
constexpr int kTagResult = 1;  // worker → rank 0: the last result (maybe empty), asking for the next job
constexpr int kTagJob = 2;     // rank 0 → worker: a job index, -1 for none

// set when a StudyMpi of several ranks was destroyed by an exception: MPI is left running for the abort
std::atomic<bool> g_failed_with_mpi_running{false};
}  // namespace

StudyMpi::StudyMpi() : exceptions_at_start_(std::uncaught_exceptions()) {
#ifdef PROXSIM_HAVE_MPI
  // launched by mpirun with several ranks, or by a PMI launcher (srun)
  const char* world_size = std::getenv("OMPI_COMM_WORLD_SIZE");
  const bool by_mpirun = world_size != nullptr && std::atoi(world_size) >= 2;
  const bool by_pmi = std::getenv("PMIX_RANK") != nullptr || std::getenv("PMI_RANK") != nullptr;
  if (!by_mpirun && !by_pmi) return;
  int provided = 0;
  // only rank 0's dispatcher thread calls MPI while other threads run
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  if (provided < MPI_THREAD_SERIALIZED) throw std::runtime_error("this MPI does not support MPI_THREAD_SERIALIZED");
  started_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

StudyMpi::~StudyMpi() {
#ifdef PROXSIM_HAVE_MPI
  if (!started_) return;
  // left by a failure: the other ranks may wait for this one; the CLI aborts the job once the message is out
  if (size_ > 1 && std::uncaught_exceptions() > exceptions_at_start_) {
    g_failed_with_mpi_running = true;
    return;
  }
  MPI_Finalize();
#endif
}

void AbortMpiJobAfterFailure([[maybe_unused]] int exit_code) {
#ifdef PROXSIM_HAVE_MPI
  if (!g_failed_with_mpi_running) return;
  std::fflush(stdout);
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, exit_code);
#endif
}

long StudyMpi::ExchangeWithWriter([[maybe_unused]] const std::string& result) {
#ifdef PROXSIM_HAVE_MPI
  MPI_Send(result.data(), static_cast<int>(result.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
  long job = -1;
  MPI_Recv(&job, 1, MPI_LONG, 0, kTagJob, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return job;
#else
  return -1;
#endif
}

void StudyMpi::ServeWorkers([[maybe_unused]] const std::function<long()>& take,
                            [[maybe_unused]] const std::function<void(const std::string&)>& on_result) {
#ifdef PROXSIM_HAVE_MPI
  int active = size_ - 1;
  std::string buffer;
  while (active > 0) {
    // poll, sleeping in between: a blocking probe spins on its core, which
    // this rank's own worker thread needs
    MPI_Status status;
    int arrived = 0;
    for (;;) {
      MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &arrived, &status);
      if (arrived) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    buffer.resize(static_cast<std::size_t>(length));
    MPI_Recv(buffer.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    // the worker's next job first, then the result: recording it (the journal's
    // fsync) must not keep the worker waiting
    long job = take();
    MPI_Send(&job, 1, MPI_LONG, status.MPI_SOURCE, kTagJob, MPI_COMM_WORLD);
    if (job < 0) --active;
    if (!buffer.empty()) on_result(buffer);
  }
#endif
}

}  // namespace proxsim
