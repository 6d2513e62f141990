#include "errormodels/imu_model.hpp"
