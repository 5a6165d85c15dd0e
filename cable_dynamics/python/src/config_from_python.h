#pragma once
/// \file
/// \brief A Python config (nested dicts, lists, numbers, strings, booleans) as the YAML tree the core's
///        config loader reads, so a dict goes through exactly the checks a config file does.

#include <string>

#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

namespace cable_dynamics {
namespace python {

/// Converts `value` (found at dotted `path`, "" for the root) into a YAML node: dict -> mapping (string
/// keys), list / tuple / numpy array -> sequence, bool, int, float, str -> scalar. Throws
/// pybind11::type_error naming the path and the Python type of anything else (None included). Ranges and
/// key names are not checked here: parseConfig does that, naming the key.
YAML::Node toYaml(const pybind11::handle& value, const std::string& path = "");

}  // namespace python
}  // namespace cable_dynamics
