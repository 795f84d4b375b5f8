#ifndef bilayer_tasks_h
#define bilayer_tasks_h

#include <deal.II/base/thread_management.h>

#include <exception>
#include <functional>
#include <memory>
#include <vector>

namespace bilayer
{
  /**
   * Functions run as parallel tasks whose exceptions reach the caller.
   * deal.II 9.4's Threads::TaskGroup<void>::join_all() waits for its tasks
   * but drops what they throw (the future of a void task is never read), so
   * an error in an assembly or a factorisation would go unnoticed. join_all()
   * here rethrows the first exception, in the order the tasks were added.
   */
  class Tasks
  {
  public:
    void
    add(const std::function<void()> &function)
    {
      auto error = std::make_shared<std::exception_ptr>();
      errors.push_back(error);
      group += dealii::Threads::new_task([function, error]() {
        try
          {
            function();
          }
        catch (...)
          {
            *error = std::current_exception();
          }
      });
    }

    void
    join_all()
    {
      group.join_all();
      for (const auto &error : errors)
        if (*error)
          std::rethrow_exception(*error);
    }

  private:
    dealii::Threads::TaskGroup<void>                 group;
    std::vector<std::shared_ptr<std::exception_ptr>> errors;
  };
} // namespace bilayer

#endif
