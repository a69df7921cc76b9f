#pragma once
// an include without its folder
#include "units.hpp"
