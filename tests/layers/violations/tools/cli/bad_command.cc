// A deliberate violation for tests/layers: the command line includes a concrete camera.
#include "sensors/camera/camera_sensor.h"
#include "tools/jobs/run_job.h"
