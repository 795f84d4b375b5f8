#ifndef bilayer_tests_study_outcome_h
#define bilayer_tests_study_outcome_h

#include <bilayer/drivers/study.h>

#include <vector>

/// What the tests that compare runs read of a Study: whether it was
/// accepted, the energy of every cycle, G at the tips of the last.
struct StudyOutcome
{
  bool                                    accepted = false;
  std::vector<double>                     energies;
  std::vector<bilayer::EnergyReleaseRate> release;
};

/// The outcome of @p study after its run(), which returned @p accepted.
inline StudyOutcome
study_outcome(const bilayer::Study &study, const bool accepted)
{
  StudyOutcome r;
  r.accepted = accepted;
  for (const auto &record : study.records())
    r.energies.push_back(record.energy);
  if (!study.records().empty())
    r.release = study.records().back().release;
  return r;
}

#endif
