#include "core/flame/Flame.h"

#include "core/flame/Variations.h"

namespace awb::flame {

FlameXform::FlameXform() : variations{{0, 1.0}}, parameters(defaultParameters()) {}

} // namespace awb::flame
