// clean: three_mode (floor 2 of sim) includes integrate (floor 0), its own room and mechanism
#include "sim/integrate/bad.hpp"
#include "sim/three_mode/model.hpp"
#include "mechanism/rig.hpp"
