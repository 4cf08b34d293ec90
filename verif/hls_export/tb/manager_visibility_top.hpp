// Testbench case of manager_visibility_top (hls/manager/visibility.hpp): a channel's setup and one
// object's bounding sphere in; the visual flag V[i], the planes the sphere is certainly outside,
// its eye-space centre and widened radius out.
#pragma once

#include "fields_manager.hpp"
#include "hls/manager/visibility.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(ManagerVisibilityTopCase, manager_visibility_top)
