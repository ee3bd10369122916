// SPDX-License-Identifier: Apache-2.0
// The OBS filter's dialog: one property per field of PropertyValues (plugins/obs/settings.h),
// named as the field and as `ifsfx filter`'s flag, read from and defaulted into obs_data.
#pragma once

#include <string>

#include <obs-module.h>

#include "plugins/obs/settings.h"

namespace ifsfx::obs {

// The name of the text property that shows why settings are not in use (empty: hidden).
inline constexpr const char* kStatus = "status";

void set_defaults(obs_data_t* data);
PropertyValues read_values(obs_data_t* data);

// The properties, `status` shown as an error line when it is not empty.
obs_properties_t* make_properties(const std::string& status);

}  // namespace ifsfx::obs
