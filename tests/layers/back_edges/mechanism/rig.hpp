#pragma once
// back edge: mechanism (layer 1) includes sim (layer 2)
#include "sim/scene.hpp"
