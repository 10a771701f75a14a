// The study's MPI layer (OpenMPI from Debian): rank 0 hands jobs out on
// request; every other rank asks for one, runs it and sends its result with
// the next request. MPI is started only when the process was launched by
// mpirun with more than one rank (OMPI_COMM_WORLD_SIZE) or by a PMI launcher
// such as srun (PMIX_RANK, PMI_RANK); otherwise, and in a build without MPI,
// this is a single process of rank 0.
//
// A failure on any rank (an input error, a locked --out, a full disk) must
// end every rank: MPI_Finalize after a failure would wait for ranks that wait
// in MPI_Recv for it, for ever. So a StudyMpi left by an exception does not
// finalize; the CLI prints the message, then AbortMpiJobAfterFailure ends the
// whole job with MPI_Abort and the exit code.
#pragma once

#include <functional>
#include <string>

namespace proxsim {

class StudyMpi {
 public:
  StudyMpi();
  ~StudyMpi();
  StudyMpi(const StudyMpi&) = delete;
  StudyMpi& operator=(const StudyMpi&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// A worker rank: sends the last result (empty at first) and receives the next job, -1 when none is left.
  long ExchangeWithWriter(const std::string& result);

  /// Rank 0, from one thread: answers every request with take() until each
  /// other rank got -1; hands every result received to `on_result`.
  void ServeWorkers(const std::function<long()>& take, const std::function<void(const std::string&)>& on_result);

 private:
  int rank_ = 0;
  int size_ = 1;
  bool started_ = false;
  int exceptions_at_start_ = 0;  ///< std::uncaught_exceptions() when made: more at destruction means a failure
};

/// After a failure's message is printed: when a study's MPI job of several
/// ranks was left by that failure, ends every rank with MPI_Abort(exit_code)
/// (never returns); otherwise does nothing.
void AbortMpiJobAfterFailure(int exit_code);

}  // namespace proxsim
