// beside-neighbour: analyze and virtual_rig share layer 3
#include "analyze/x.hpp"
#include "virtual_rig/virtual_rig.hpp"
