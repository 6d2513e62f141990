#include "nav/strapdown.hpp"
