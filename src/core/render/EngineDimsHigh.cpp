// The engine's fixed-dimension kernels for IFS of dimension 9 to 12, deterministic and
// random, in each of the four Stores (core/render/EngineRun.h).
#include "core/render/EngineRun.h"

namespace awb::engine {

AWB_ENGINE_DIMS(9, kMaxFixedDim);

} // namespace awb::engine
