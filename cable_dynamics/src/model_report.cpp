#include "cable_dynamics/model_report.h"

#include "cable_dynamics/elastic_joints.h"
#include "cable_dynamics/paper_model.h"

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
  const int dof = 3 * props.n;
  PaperModel model(props);
  ElasticJoints joints(props);
  Eigen::MatrixXd M(dof, dof), K(dof, dof), D(dof, dof);
  Eigen::VectorXd h(dof), G(dof), elastic(dof);
  model.compute(q, qd, M, h, G);
  joints.stiffness(q, K);
  joints.force(q, elastic);
  joints.damping(D);
  Eigen::Matrix3Xd ends(3, props.n + 1);
  model.linkEnds(q, ends);

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
  j["load_mass"] = props.load_mass;
  j["load_submerged_mass"] = props.load_submerged_mass;
  j["gravity"] = props.gravity;
  j["stiffness_model"] = props.stiffness_model == StiffnessModel::kPaper ? "paper" : "bending";
  j["M"] = toJson(M);
  j["h"] = toJson(h);
  j["G"] = toJson(G);
  j["K"] = toJson(K);
  j["elastic"] = toJson(elastic);
  j["D"] = toJson(D);
  j["elastic_energy"] = joints.energy(q);
  j["potential_energy"] = model.potentialEnergy(q);
  j["kinetic_energy"] = 0.5 * qd.dot(M * qd);
  nlohmann::json end_points = nlohmann::json::array();
  for (int k = 0; k <= props.n; ++k) end_points.push_back({ends(0, k), ends(1, k), ends(2, k)});
  j["link_ends"] = end_points;
  return j;
}

}  // namespace cable_dynamics
