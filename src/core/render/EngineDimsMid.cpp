// The engine's fixed-dimension kernels for IFS of dimension 5 to 8, deterministic and
// random, in each of the four Stores (core/render/EngineRun.h).
#include "core/render/EngineRun.h"

namespace awb::engine {

AWB_ENGINE_DIMS(5, 8);

} // namespace awb::engine
