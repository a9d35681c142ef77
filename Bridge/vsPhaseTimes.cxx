#include "vsPhaseTimes.h"

namespace vs
{
void PhaseTimes::Add(const std::string& name, double seconds)
{
  for (auto& phase : this->Phases_)
  {
    if (phase.first == name)
    {
      phase.second += seconds;
      return;
    }
  }
  this->Phases_.emplace_back(name, seconds);
}

PhaseTimes::Clock::time_point PhaseTimes::Lap(const std::string& name, Clock::time_point since)
{
  const Clock::time_point now = Clock::now();
  this->Add(name, std::chrono::duration<double>(now - since).count());
  return now;
}

void PhaseTimes::Append(const std::string& prefix, const PhaseTimes& other)
{
  for (const auto& phase : other.Phases_)
  {
    this->Add(prefix + phase.first, phase.second);
  }
}

double PhaseTimes::Seconds(const std::string& name) const
{
  for (const auto& phase : this->Phases_)
  {
    if (phase.first == name)
    {
      return phase.second;
    }
  }
  return 0.0;
}
}
