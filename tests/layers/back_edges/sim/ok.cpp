// clean: sim (layer 2) includes mechanism (layer 1) and common (layer 0)
#include "mechanism/rig.hpp"
#include "common/units.hpp"
#include <vector>
