// The one copy of the decompositions that core/Decompositions.h declares.
#include "core/Decompositions.h"

AWB_EIGEN_DECOMPOSITIONS()
