#include "config_from_python.h"

namespace py = pybind11;

namespace cable_dynamics {
namespace python {
namespace {

std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string typeName(const py::handle& value) { return py::str(py::type::handle_of(value).attr("__name__")); }

}  // namespace

YAML::Node toYaml(const py::handle& value, const std::string& path) {
  const std::string where = path.empty() ? "the config" : "key '" + path + "'";
  // bool before int: Python's bool is an int.
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return YAML::Node(value.cast<long long>());
  // float, numpy.float64 (a float subclass); yaml-cpp writes doubles with max_digits10 and NaN/inf as
  // .nan/.inf, which the loader reads back and rejects by key.
  if (py::isinstance<py::float_>(value)) return YAML::Node(value.cast<double>());
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& item : py::reinterpret_borrow<py::dict>(value)) {
      if (!py::isinstance<py::str>(item.first)) {
        throw py::type_error(where + ": keys must be strings, got a " + typeName(item.first));
      }
      const std::string key = item.first.cast<std::string>();
      map[key] = toYaml(item.second, child(path, key));
    }
    return map;
  }
  // numpy arrays and numpy scalars other than float64 (int64, float32, ...): through their Python values.
  if (py::hasattr(value, "tolist") && !py::isinstance<py::list>(value)) return toYaml(value.attr("tolist")(), path);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node seq(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const auto& item : value) seq.push_back(toYaml(item, path + "[" + std::to_string(i++) + "]"));
    return seq;
  }
  throw py::type_error(where + ": expected a dict, list, number, string or bool, got " + typeName(value));
}

}  // namespace python
}  // namespace cable_dynamics
