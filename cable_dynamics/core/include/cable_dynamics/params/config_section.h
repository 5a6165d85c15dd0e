#pragma once
/// \file
/// \brief Validated reads from one section of a YAML tree: every config key (config_loader.h) and every
///        node option (`ros.*`) goes through these, so all are checked and reported the same way.

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "cable_dynamics/params/key_ranges.h"

namespace cable_dynamics {

/// A bad configuration value: the message names the key, the value and the allowed range.
class ConfigError : public std::invalid_argument {
 public:
  ConfigError(const std::string& key, const std::string& value, const std::string& expected);
  /// Dotted path of the offending key, e.g. "cable.links".
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

/// A node's value as it reads in a message: flow YAML, or "(missing)".
std::string describeNode(const YAML::Node& node);

/// A hook for tests: while one exists (on this thread), every key a ConfigSection is asked for is
/// recorded by its dotted path (list entries with their index, e.g. `cable.sections[0].length`).
/// test/test_config_keys.cpp lists the loader's keys with it against docs/CONFIG.md.
class ConfigKeyLog {
 public:
  ConfigKeyLog();
  ~ConfigKeyLog();
  ConfigKeyLog(const ConfigKeyLog&) = delete;
  ConfigKeyLog& operator=(const ConfigKeyLog&) = delete;
  /// The keys asked for, less those opened as sub-sections (mappings of further keys).
  std::set<std::string> keys() const;
  /// The keys read with a range (numbers, integers, lists of numbers), by the key of the whole list.
  const std::set<std::string>& rangedKeys() const { return ranged_; }
  /// The keys the gate checked against their range (checkConfigRanges: logCheckedKey).
  const std::set<std::string>& checkedKeys() const { return checked_; }

 private:
  friend class ConfigSection;
  friend void logCheckedKey(const std::string& key);
  ConfigKeyLog* previous_;
  std::set<std::string> asked_, sections_, ranged_, checked_;
};

/// Records `key` as checked by the gate in the active ConfigKeyLog, if any (params/range_gate.cpp).
void logCheckedKey(const std::string& key);

/// One section (mapping) of a YAML tree: typed reads with range checks, and a check that no other keys
/// are present. A number must be a plain scalar: a quoted string such as '25' is refused where a number
/// is expected, as is a fraction where an integer is.
class ConfigSection {
 public:
  /// `path` is the section's dotted path ("" for the root). Throws ConfigError when `node` is neither
  /// absent nor a mapping.
  ConfigSection(const YAML::Node& node, std::string path);

  /// true when `key` is present and not null (and marks it known).
  bool has(const std::string& key);
  /// The sub-section `key` (an empty one when absent).
  ConfigSection sub(const std::string& key);

  /// A finite number in `range` (params/key_ranges.h); `fallback` when absent and not `required`.
  double number(const std::string& key, double fallback, const NumberRange& range, bool required = false);
  /// The same with the range written out: [lo, hi], or (lo, hi] when `lo_open`; `unit` for messages.
  double number(const std::string& key, double fallback, double lo, double hi, bool lo_open, const char* unit,
                bool required = false) {
    return number(key, fallback, NumberRange{lo, hi, lo_open, unit}, required);
  }
  /// An integer in `range` (no fraction, no exponent, no quotes).
  int integer(const std::string& key, int fallback, const IntegerRange& range, bool required = false);
  int integer(const std::string& key, int fallback, int lo, int hi, bool required) {
    return integer(key, fallback, IntegerRange{lo, hi}, required);
  }
  /// One of `allowed`.
  std::string choice(const std::string& key, const std::string& fallback, const std::set<std::string>& allowed);
  /// A scalar (applied to every joint) or a list of exactly `count` numbers, each in `range`.
  std::vector<double> perJoint(const std::string& key, int count, const NumberRange& range);
  /// A list of exactly `count` finite numbers, each in `range`.
  std::vector<double> numberList(const std::string& key, int count, const NumberRange& range);
  std::vector<double> numberList(const std::string& key, int count, double lo, double hi, bool lo_open,
                                 const char* unit) {
    return numberList(key, count, NumberRange{lo, hi, lo_open, unit});
  }
  /// A string scalar that `valid` accepts; `expected` describes what is allowed.
  std::string text(const std::string& key, const std::string& fallback, bool (*valid)(const std::string&),
                   const std::string& expected);

  /// Every key present must have been asked for: a misspelt key is an error, never silently ignored.
  void rejectUnknownKeys() const;

  const std::string& path() const { return path_; }
  /// The raw node of a key (marks it known).
  YAML::Node raw(const std::string& key);

 private:
  YAML::Node at(const std::string& key) const;
  std::string full(const std::string& key) const;
  /// Marks `key` known (and records it in an active ConfigKeyLog; `section`: opened by sub()).
  void mark(const std::string& key, bool section = false);
  /// Records `key` as read with a range in an active ConfigKeyLog.
  void markRanged(const std::string& key) const;

  YAML::Node node_;
  std::string path_;
  std::set<std::string> known_;
};

}  // namespace cable_dynamics
