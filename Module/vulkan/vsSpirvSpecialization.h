// vsSpirvSpecialization.h — a SPIR-V module with its specialization constants' values folded in
// before the driver sees it: the constants frozen, the branches they decide and the functions no
// branch reaches any more removed (SPIRV-Tools' optimizer; no inlining, no other rewriting).
//
// Why: the render kernel is one module whose features (full transport or single scattering, the
// camera estimator, the cell walk, cropping, the surface lobe, VTK's lights, ...) are chosen by
// specialization constants. A driver may fold them after inlining every call (Mesa 22.3's lavapipe
// does: spirv_to_nir, then nir_inline_functions, and only then dead control flow), so it inlines
// and optimizes the code of every feature, selected or not: 71,000 SPIR-V instructions inlined for
// 10,000 that run (Environment sampling, full transport). Folded here first, the driver compiles
// only what runs: the first render kernel's pipeline on lavapipe took 0.75-0.9 s, and takes
// 0.15 s plus this pass's 0.07-0.12 s (docs/benchmarks.md, "The render kernel's compile").
#ifndef vsSpirvSpecialization_h
#define vsSpirvSpecialization_h

#include "vissweepCoreModule.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vs
{
/** The module `spirv` (`bytes` long, a whole number of words) with specialization constant i set to
 *  constants[i] and frozen, and the code those values make unreachable removed. Returns an empty
 *  vector and says why in `problem` when the optimizer cannot (the caller then gives the driver the
 *  module as it is, with the constants as specialization info: the same kernel, compiled slower). */
VISSWEEPCORE_EXPORT std::vector<uint32_t> SpecializeSpirv(
  const uint32_t* spirv, size_t bytes, const std::vector<uint32_t>& constants, std::string& problem);
}

#endif
