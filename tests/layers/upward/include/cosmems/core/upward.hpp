#pragma once

// A core header that reaches up into time/: check_layers.sh must reject it.
#include "cosmems/time/newton_options.hpp"
