#include "cable_dynamics/params/config_section.h"

#include <cmath>
#include <sstream>

namespace cable_dynamics {
namespace {

std::string join(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

/// A scalar written as a string ('25' or "25" in YAML; a string on the parameter server, which
/// node_options.cpp tags "!") is not a number, whatever its characters.
bool isQuoted(const YAML::Node& v) { return v.Tag() == "!"; }

double checkNumber(const YAML::Node& v, const std::string& full, const NumberRange& range) {
  const std::string expected = range.text();
  double value = 0.0;
  try {
    if (!v.IsScalar() || isQuoted(v)) throw YAML::Exception(YAML::Mark::null_mark(), "not a plain scalar");
    value = v.as<double>();
  } catch (const YAML::Exception&) {
    throw ConfigError(full, describeNode(v), expected);
  }
  if (!range.allows(value)) throw ConfigError(full, describeNode(v), expected);
  return value;
}

}  // namespace

ConfigError::ConfigError(const std::string& key, const std::string& value, const std::string& expected)
    : std::invalid_argument("config key '" + key + "' = " + value + ": expected " + expected), key_(key) {}

std::string describeNode(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "(missing)";
  if (node.IsScalar() && isQuoted(node)) return "'" + node.Scalar() + "' (a string)";
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

ConfigSection::ConfigSection(const YAML::Node& node, std::string path) : node_(node), path_(std::move(path)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw ConfigError(path_, describeNode(node_), "a mapping of keys");
  }
}

YAML::Node ConfigSection::at(const std::string& key) const {
  // Read-only lookup: yaml-cpp's non-const operator[] would insert the key into the tree.
  const YAML::Node& node = node_;
  return node[key];
}

std::string ConfigSection::full(const std::string& key) const { return join(path_, key); }

namespace {
thread_local ConfigKeyLog* active_log = nullptr;
}  // namespace

ConfigKeyLog::ConfigKeyLog() : previous_(active_log) { active_log = this; }

ConfigKeyLog::~ConfigKeyLog() { active_log = previous_; }

std::set<std::string> ConfigKeyLog::keys() const {
  std::set<std::string> out;
  for (const std::string& k : asked_) {
    if (sections_.count(k) == 0) out.insert(k);
  }
  return out;
}

void ConfigSection::mark(const std::string& key, bool section) {
  known_.insert(key);
  if (active_log != nullptr) (section ? active_log->sections_ : active_log->asked_).insert(full(key));
}

void ConfigSection::markRanged(const std::string& key) const {
  if (active_log != nullptr) active_log->ranged_.insert(full(key));
}

void logCheckedKey(const std::string& key) {
  if (active_log != nullptr) active_log->checked_.insert(key);
}

bool ConfigSection::has(const std::string& key) {
  mark(key);
  return node_.IsDefined() && !node_.IsNull() && at(key).IsDefined() && !at(key).IsNull();
}

ConfigSection ConfigSection::sub(const std::string& key) {
  mark(key, true);
  return ConfigSection(has(key) ? at(key) : YAML::Node(), full(key));
}

YAML::Node ConfigSection::raw(const std::string& key) {
  mark(key);
  return at(key);
}

double ConfigSection::number(const std::string& key, double fallback, const NumberRange& range, bool required) {
  markRanged(key);
  if (!has(key)) {
    if (required) throw ConfigError(full(key), "(missing)", range.text());
    return fallback;
  }
  return checkNumber(at(key), full(key), range);
}

int ConfigSection::integer(const std::string& key, int fallback, const IntegerRange& range, bool required) {
  markRanged(key);
  const std::string name = full(key);
  const std::string expected = range.text();
  if (!has(key)) {
    if (required) throw ConfigError(name, "(missing)", expected);
    return fallback;
  }
  const YAML::Node v = at(key);
  long value = 0;
  try {
    if (!v.IsScalar() || isQuoted(v)) throw std::invalid_argument("not a plain scalar");
    const std::string text = v.Scalar();
    std::size_t used = 0;
    value = std::stol(text, &used);
    if (used != text.size()) throw std::invalid_argument("trailing characters");
  } catch (const std::exception&) {
    throw ConfigError(name, describeNode(v), expected);
  }
  if (!range.allows(value)) throw ConfigError(name, describeNode(v), expected);
  return static_cast<int>(value);
}

std::string ConfigSection::choice(const std::string& key, const std::string& fallback,
                                  const std::set<std::string>& allowed) {
  if (!has(key)) return fallback;
  const YAML::Node v = at(key);
  std::string expected = "one of";
  for (const auto& a : allowed) expected += " " + a;
  if (!v.IsScalar() || allowed.count(v.Scalar()) == 0) throw ConfigError(full(key), describeNode(v), expected);
  return v.Scalar();
}

std::vector<double> ConfigSection::perJoint(const std::string& key, int count, const NumberRange& range) {
  markRanged(key);
  const std::string name = full(key);
  if (!has(key)) return std::vector<double>(count, 0.0);
  const YAML::Node v = at(key);
  if (v.IsSequence()) {
    if (static_cast<int>(v.size()) != count) {
      throw ConfigError(name, describeNode(v),
                        "a number or a list of " + std::to_string(count) + " numbers (one per joint)");
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      out.push_back(checkNumber(v[i], name + "[" + std::to_string(i) + "]", range));
    }
    return out;
  }
  return std::vector<double>(count, checkNumber(v, name, range));
}

std::vector<double> ConfigSection::numberList(const std::string& key, int count, const NumberRange& range) {
  mark(key);
  markRanged(key);
  const std::string name = full(key);
  const YAML::Node v = at(key);
  if (!v.IsSequence() || static_cast<int>(v.size()) != count) {
    throw ConfigError(name, describeNode(v), "a list of " + std::to_string(count) + " numbers");
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.push_back(checkNumber(v[i], name + "[" + std::to_string(i) + "]", range));
  }
  return out;
}

std::string ConfigSection::text(const std::string& key, const std::string& fallback,
                                bool (*valid)(const std::string&), const std::string& expected) {
  if (!has(key)) return fallback;
  const YAML::Node v = at(key);
  if (!v.IsScalar() || !valid(v.Scalar())) throw ConfigError(full(key), describeNode(v), expected);
  return v.Scalar();
}

void ConfigSection::rejectUnknownKeys() const {
  if (!node_.IsDefined() || node_.IsNull()) return;
  for (const auto& kv : node_) {
    const std::string key = kv.first.as<std::string>();
    if (known_.count(key) == 0) {
      std::string expected = "no such key; known keys here:";
      for (const auto& k : known_) expected += " " + k;
      throw ConfigError(join(path_, key), describeNode(kv.second), expected);
    }
  }
}

}  // namespace cable_dynamics
