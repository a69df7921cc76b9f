// back edge: integrate (floor 0 of sim) includes three_mode (floor 2)
#include <vector>
#include "sim/three_mode/model.hpp"
