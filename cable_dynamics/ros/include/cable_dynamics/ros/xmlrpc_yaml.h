#pragma once
/// \file
/// \brief The parameter server's tree as YAML, so the config loader checks the node's parameters exactly as
///        it checks a file.

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

namespace cable_dynamics {

/// Converts an XmlRpc value (what `getParam("")` gives) to a YAML node. A string becomes a scalar tagged
/// "!" (as a quoted YAML scalar is), so that ConfigSection refuses '25' where a number is expected; a
/// double keeps its full precision, and NaN/inf become .nan/.inf, which the checks then refuse by key.
YAML::Node xmlRpcToYaml(XmlRpc::XmlRpcValue& value);

}  // namespace cable_dynamics
