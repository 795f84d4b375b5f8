#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <bilayer/subproblem/distribution.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <string>

namespace bilayer
{
  using namespace dealii;

  Distribution::Distribution()
    : communicator_(MPI_COMM_SELF)
    , group_communicator_(MPI_COMM_SELF)
  {}


  Distribution::Distribution(const MPI_Comm communicator)
    : communicator_(communicator)
    , group_communicator_(MPI_COMM_SELF)
    , n_processes_(Utilities::MPI::n_mpi_processes(communicator))
    , process_(Utilities::MPI::this_mpi_process(communicator))
  {
    if (n_processes_ > max_groups)
      {
        const int ierr = MPI_Comm_split(communicator_,
                                        static_cast<int>(process_ % max_groups),
                                        static_cast<int>(process_),
                                        &group_communicator_);
        AssertThrowMPI(ierr);
        own_group_communicator = true;
      }
  }


  Distribution::~Distribution()
  {
    // The distribution of the whole job lives until after MPI_Finalize.
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (own_group_communicator && !finalized)
      MPI_Comm_free(&group_communicator_);
  }


  const Distribution &
  Distribution::world()
  {
    static const Distribution serial;
    if (!Utilities::MPI::job_supports_mpi())
      return serial;
    static const Distribution all(MPI_COMM_WORLD);
    return all;
  }


  bool
  Distribution::owns(const unsigned int s) const
  {
    return n_processes_ <= max_groups ? s % n_processes_ == process_ :
                                        process_ % max_groups == s;
  }


  unsigned int
  Distribution::group_size(const unsigned int s) const
  {
    // The processes p with p mod n_subproblems = s.
    return n_processes_ <= max_groups ?
             1 :
             (n_processes_ - s + max_groups - 1) / max_groups;
  }


  void
  Distribution::share(const unsigned int                          s,
                      Vector<double>                             &v,
                      const std::vector<types::global_dof_index> *indices) const
  {
    if (!parallel())
      return;
    Timer timer;
    int   ierr;
    if (indices != nullptr)
      {
        std::vector<double> buffer(indices->size());
        if (process_ == root(s))
          for (unsigned int i = 0; i < indices->size(); ++i)
            buffer[i] = v((*indices)[i]);
        ierr = MPI_Bcast(buffer.data(),
                         static_cast<int>(buffer.size()),
                         MPI_DOUBLE,
                         static_cast<int>(root(s)),
                         communicator_);
        for (unsigned int i = 0; i < indices->size(); ++i)
          v((*indices)[i]) = buffer[i];
      }
    else
      ierr = MPI_Bcast(v.begin(),
                       static_cast<int>(v.size()),
                       MPI_DOUBLE,
                       static_cast<int>(root(s)),
                       communicator_);
    AssertThrowMPI(ierr);
    shared_values_ += indices != nullptr ? indices->size() : v.size();
    shared_seconds_ += timer.wall_time();
  }


  void
  Distribution::share(PerSubproblem<double> &values) const
  {
    if (!parallel())
      return;
    PerSubproblem<double> own(values.size(), 0.);
    for (const unsigned int s : Layout::indices(values.size()))
      if (process_ == root(s))
        own[s] = values[s];
    // Exactly one non-zero contribution per entry: the sum is exact.
    const int ierr = MPI_Allreduce(own.data(),
                                   values.data(),
                                   own.size(),
                                   MPI_DOUBLE,
                                   MPI_SUM,
                                   communicator_);
    AssertThrowMPI(ierr);
  }


  double
  Distribution::max(const double value) const
  {
    return parallel() ? Utilities::MPI::max(value, communicator_) : value;
  }


  std::vector<double>
  Distribution::gather(const double value) const
  {
    if (!parallel())
      return {value};
    return Utilities::MPI::gather(communicator_, value, 0);
  }


  void
  Distribution::barrier() const
  {
    if (parallel())
      {
        const int ierr = MPI_Barrier(communicator_);
        AssertThrowMPI(ierr);
      }
  }


  void
  Distribution::broadcast(bool &flag, std::string &message) const
  {
    if (!parallel())
      return;
    std::pair<bool, std::string> data(flag, message);
    data    = Utilities::MPI::broadcast(communicator_, data, 0);
    flag    = data.first;
    message = data.second;
  }


  std::string
  Distribution::first_error(const std::string &message) const
  {
    if (!parallel())
      return message;
    for (const auto &m : Utilities::MPI::all_gather(communicator_, message))
      if (!m.empty())
        return m;
    return "";
  }
} // namespace bilayer
