#include "cable_dynamics/ros/xmlrpc_yaml.h"

#include <string>

namespace cable_dynamics {

YAML::Node xmlRpcToYaml(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(value));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return YAML::Node(static_cast<double>(value));
    case XmlRpc::XmlRpcValue::TypeString: {
      YAML::Node text(static_cast<std::string>(value));
      text.SetTag("!");  // a string, never a number, whatever its characters
      return text;
    }
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node sequence(YAML::NodeType::Sequence);
      for (int i = 0; i < value.size(); ++i) sequence.push_back(xmlRpcToYaml(value[i]));
      return sequence;
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto& kv : value) map[kv.first] = xmlRpcToYaml(kv.second);
      return map;
    }
    default: {
      // Date/time, base64 or an invalid value: a string the checks refuse wherever a number or a name is
      // expected, with its XML spelling in the message.
      YAML::Node other(value.toXml());
      other.SetTag("!");
      return other;
    }
  }
}

}  // namespace cable_dynamics
