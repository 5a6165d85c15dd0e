#include "cable_dynamics/tools/model_report.h"

#include "cable_dynamics/dynamics/paper_model.h"

namespace cable_dynamics {
namespace {

nlohmann::json toJson(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

nlohmann::json toJson(const Eigen::MatrixXd& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < m.rows(); ++i) rows.push_back(toJson(Eigen::VectorXd(m.row(i).transpose())));
  return rows;
}

}  // namespace

nlohmann::json modelReport(const CableParams& params, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
  const LinkProperties props = deriveLinkProperties(params);
  const PaperModelTerms t = paperModelAt(props, q, qd);
  Eigen::Matrix3Xd ends(3, props.n + 1);
  PaperModel(props).linkEnds(q, ends);

  nlohmann::json j;
  j["n"] = props.n;
  j["coordinates"] = coordinateNames(props.n);
  j["q"] = toJson(q);
  j["qd"] = toJson(qd);
  j["mass"] = toJson(props.mass);
  j["length"] = toJson(props.length);
  j["inertia_transverse"] = toJson(props.inertia_transverse);
  j["inertia_polar"] = toJson(props.inertia_polar);
  j["submerged_mass"] = toJson(props.submerged_mass);
  j["radius"] = toJson(props.radius);
  j["added_mass_per_length"] = toJson(props.added_mass_per_length);
  j["drag_normal"] = toJson(props.drag_normal);
  j["drag_tangential"] = toJson(props.drag_tangential);
  j["section"] = toJson(Eigen::VectorXd(props.section.cast<double>()));
  // Point attachments on their links; the paper model's M, h, G below are the cable's alone (without them).
  nlohmann::json attachments = nlohmann::json::array();
  for (const LinkAttachment& a : props.attachments) {
    attachments.push_back({{"link", a.link + 1}, {"offset", a.offset}, {"mass", a.mass}, {"submerged_mass", a.submerged_mass},
                           {"added_mass", a.added_mass}, {"drag_area", a.drag_area}});
  }
  j["attachments"] = attachments;
  j["load_mass"] = props.load_mass;
  j["load_submerged_mass"] = props.load_submerged_mass;
  j["gravity"] = props.gravity;
  j["stiffness_model"] = props.stiffness_model == StiffnessModel::kPaper ? "paper" : "bending";
  j["M"] = toJson(t.M);
  j["h"] = toJson(t.h);
  j["G"] = toJson(t.G);
  j["K"] = toJson(t.K);
  j["elastic"] = toJson(t.elastic);
  j["D"] = toJson(t.D);
  j["elastic_energy"] = t.elastic_energy;
  j["potential_energy"] = t.potential_energy;
  j["kinetic_energy"] = t.kinetic_energy;
  nlohmann::json end_points = nlohmann::json::array();
  for (int k = 0; k <= props.n; ++k) end_points.push_back({ends(0, k), ends(1, k), ends(2, k)});
  j["link_ends"] = end_points;
  return j;
}

}  // namespace cable_dynamics
