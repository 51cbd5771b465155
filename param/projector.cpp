#include "core/math.h"
