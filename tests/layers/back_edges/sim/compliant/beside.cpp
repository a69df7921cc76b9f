// back edge: compliant includes linkage, its neighbour on floor 3 of sim
#include <vector>
#include "sim/linkage/linkage_model.hpp"
