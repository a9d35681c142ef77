#include "vsParallelSlabs.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace vs
{
unsigned HostThreads()
{
  if (const char* env = std::getenv("VISSWEEP_HOST_THREADS"))
  {
    const long n = std::strtol(env, nullptr, 10);
    if (n >= 1)
    {
      return unsigned(std::min(n, 64L));
    }
  }
  return std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
}

unsigned SlabCount(uint64_t count)
{
  return unsigned(std::max<uint64_t>(1, std::min<uint64_t>(HostThreads(), count)));
}

void ForSlabs(uint64_t count, const std::function<void(unsigned slab, uint64_t begin, uint64_t end)>& body)
{
  const unsigned slabs = SlabCount(count);
  auto range = [&](unsigned s, uint64_t& begin, uint64_t& end) {
    begin = count * s / slabs;
    end = count * (s + 1) / slabs;
  };
  std::vector<std::exception_ptr> errors(slabs);
  auto run = [&](unsigned s) {
    uint64_t b, e;
    range(s, b, e);
    try
    {
      body(s, b, e);
    }
    catch (...)
    {
      errors[s] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  std::vector<unsigned> here = { 0 }; // the slabs this thread runs (also those no thread could start for)
  for (unsigned s = 1; s < slabs; ++s)
  {
    try
    {
      threads.emplace_back(run, s);
    }
    catch (const std::system_error&)
    {
      here.push_back(s);
    }
  }
  for (unsigned s : here)
  {
    run(s);
  }
  for (auto& t : threads)
  {
    t.join();
  }
  for (const auto& error : errors)
  {
    if (error)
    {
      std::rethrow_exception(error);
    }
  }
}
}
