// The engine's fixed-dimension kernels for IFS of dimension 1 to 4, deterministic and
// random, in each of the four Stores (core/render/EngineRun.h).
#include "core/render/EngineRun.h"

namespace awb::engine {

AWB_ENGINE_DIMS(1, 4);

} // namespace awb::engine
