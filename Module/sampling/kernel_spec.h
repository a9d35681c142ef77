/*
 * kernel_spec.h — the render kernel's specialization constants, numbered once for both sides:
 * render/mc_resources.glsl declares `layout(constant_id = VS_SPEC_ID_STRATEGY) ...`, and the host
 * sets each by the same name (vs::KernelSpecialization, render/vsKernelOptions.h), which refuses
 * a vector with an id left unset. The options that select a value of these constants, their
 * words and their API names are listed once in render/vsKernelOptions.cxx.
 */
#ifndef VS_KERNEL_SPEC_H
#define VS_KERNEL_SPEC_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

VS_CONST uint VS_SPEC_ID_STRATEGY = 0u;      /* VS_STRATEGY_* (strategies.h) */
VS_CONST uint VS_SPEC_ID_CELL_MODE = 1u;     /* VS_CELL_* (mc_params.h) */
VS_CONST uint VS_SPEC_ID_REFINE = 2u;        /* 1: some majorant segment may reach the cell walk's depth */
VS_CONST uint VS_SPEC_ID_CAMERA = 3u;        /* VS_CAMERA_* */
VS_CONST uint VS_SPEC_ID_INTERPOLATION = 4u; /* VS_INTERPOLATION_* (interpolation.h) */
VS_CONST uint VS_SPEC_ID_CROPPING = 5u;      /* 1: cropping regions */
VS_CONST uint VS_SPEC_ID_TABLE = 6u;         /* 1: the grid strategies read the direction table */
VS_CONST uint VS_SPEC_ID_DEFENSIVE = 7u;     /* 1: TwoStep mixed with Environment sampling */
VS_CONST uint VS_SPEC_ID_SKIP = 8u;          /* 1: empty-space skipping */
VS_CONST uint VS_SPEC_ID_QUADS = 9u;         /* 1: 8-bit quads for trilinear samples */
VS_CONST uint VS_SPEC_ID_CONTROL = 10u;      /* VS_CONTROL_* bits */
VS_CONST uint VS_SPEC_ID_SAMPLER = 11u;      /* VS_SAMPLER_* */
VS_CONST uint VS_SPEC_ID_FACTOR = 12u;       /* 1: the extinction scaled by the gradient opacity's factor */
VS_CONST uint VS_SPEC_ID_TRANSMITTANCE = 13u; /* VS_TRANSMITTANCE_* */
VS_CONST uint VS_SPEC_ID_PATH = 14u;         /* 1: full transport (event limit > 1 or anisotropic phase) */
VS_CONST uint VS_SPEC_ID_LOOP_BUDGET = 15u;  /* the sample loop's budget of back-edges */
VS_CONST uint VS_SPEC_ID_SURFACE = 16u;      /* 1: hybrid scattering, a surface lobe (issue 38) */
VS_CONST uint VS_SPEC_ID_LIGHTS = 17u;       /* 1: VTK's lights beside the environment (issue 38) */
VS_CONST uint VS_SPEC_ID_COUNT = 18u;        /* ids 0 .. VS_SPEC_ID_COUNT - 1, each set by the host */

VS_NAMESPACE_END

#endif
