#include "cable_dynamics/ros/xmlrpc_yaml.h"

#include <regex>
#include <string>

namespace cable_dynamics {
namespace {

/// true for a string that rosparam's YAML 1.1 reader (PyYAML) leaves a string although it is written as
/// a number: an exponent without a sign or a number without a decimal point before it, such as 1e4,
/// 2.0e7 or 5E-3, which YAML 1.2 and every other reader take as floats. A string that YAML 1.1 reads as
/// a number, such as 25 or 50.0, reached the parameter server as a string only because it was quoted.
bool unquotedYaml12Number(const std::string& text) {
  static const std::regex yaml12_float(R"(^[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?$)");
  static const std::regex yaml11_number(R"(^[-+]?(([0-9][0-9_]*)?\.[0-9.]*([eE][-+][0-9]+)?|(0|[1-9][0-9_]*))$)");
  return std::regex_match(text, yaml12_float) && !std::regex_match(text, yaml11_number);
}

}  // namespace

YAML::Node xmlRpcToYaml(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(value));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return YAML::Node(static_cast<double>(value));
    case XmlRpc::XmlRpcValue::TypeString: {
      const std::string content = static_cast<std::string>(value);
      YAML::Node text(content);
      // A string stays a string (never a number, whatever its characters), except the numbers rosparam's
      // YAML 1.1 cannot read as such: those were written unquoted.
      if (!unquotedYaml12Number(content)) text.SetTag("!");
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
