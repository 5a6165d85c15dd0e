// MuJoCo (Debian's libmujoco-dev): ball joints, MuJoCo's own RK4 (integrator="RK4": mj_step runs the
// forward dynamics 4 times and moves the quaternions with mj_integratePos at every stage).
#include <algorithm>
#include <cstring>
#include <memory>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <mujoco/mujoco.h>

#include "chain_spec.h"

namespace bench {
namespace {

/// Bodies per XML file: TinyXML2 (MuJoCo's parser) refuses elements nested deeper than 100, so the
/// chain is cut into files, each <include>d from the innermost body of the previous one (MuJoCo
/// expands the includes into one tree after parsing each file on its own).
constexpr int kBodiesPerFile = 80;

std::string fileName(int part) { return "chain" + std::to_string(part) + ".xml"; }

/// The model as files: name -> text; the first is the main file.
std::vector<std::pair<std::string, std::string>> chainXml(const ChainSpec& s) {
  std::vector<std::pair<std::string, std::string>> files;
  const int parts = (s.n + kBodiesPerFile - 1) / kBodiesPerFile;
  for (int part = 0; part < parts; ++part) {
    std::ostringstream x;
    x << std::setprecision(17);
    if (part == 0) {
      x << "<mujoco model=\"bench_chain\">\n"
        // Mass and inertia exactly as given: nothing inferred from geoms, bounded or rebalanced.
        << "<compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\" "
           "balanceinertia=\"false\"/>\n"
        << "<option timestep=\"" << s.dt << "\" integrator=\"RK4\" gravity=\"0 0 " << s.gravity
        << "\" density=\"0\" viscosity=\"0\">\n"
        // A free chain: no contacts, no constraint solver, no passive forces. Energy is computed on
        // demand outside the timed loop (the flag would add an O(n^2) M-product to every step).
        << "<flag contact=\"disable\" constraint=\"disable\" equality=\"disable\" frictionloss=\"disable\" "
           "limit=\"disable\" passive=\"disable\" actuation=\"disable\" energy=\"disable\" warmstart=\"disable\"/>\n"
        << "</option>\n<worldbody>\n";
    } else {
      x << "<mujocoinclude>\n";
    }
    const int first = part * kBodiesPerFile, last = std::min(s.n, first + kBodiesPerFile);
    for (int k = first; k < last; ++k) {
      // Body frame at the joint (the link's base end), z along the link: child k sits at (0, 0, l_{k-1}).
      x << "<body name=\"l" << k << "\" pos=\"0 0 " << (k == 0 ? 0.0 : s.length[k - 1]) << "\">"
        << "<joint type=\"ball\" damping=\"0\" armature=\"0\" stiffness=\"0\"/>"
        << "<inertial pos=\"0 0 " << s.bodyCom(k) << "\" mass=\"" << s.bodyMass(k) << "\" diaginertia=\""
        << s.bodyInertiaTransverse(k) << " " << s.bodyInertiaTransverse(k) << " " << s.bodyInertiaPolar(k) << "\"/>";
      if (k == s.n - 1) x << "<site name=\"tip\" pos=\"0 0 " << s.length[k] << "\"/>";
      x << "\n";
    }
    if (part + 1 < parts) x << "<include file=\"" << fileName(part + 1) << "\"/>\n";
    for (int k = first; k < last; ++k) x << "</body>";
    x << (part == 0 ? "\n</worldbody>\n</mujoco>\n" : "\n</mujocoinclude>\n");
    files.emplace_back(fileName(part), x.str());
  }
  return files;
}

/// MuJoCo's warnings go here instead of MUJOCO_LOG.TXT in the working directory.
std::string& lastWarning() {
  static std::string text;
  return text;
}
void recordWarning(const char* message) { lastWarning() = message; }

class MujocoSystem : public System {
 public:
  explicit MujocoSystem(const ChainSpec& spec) : spec_(spec) {
    mju_user_warning = &recordWarning;
    lastWarning().clear();
    // The files live in MuJoCo's in-memory file system (mjVFS), nothing is written to disk.
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    const auto files = chainXml(spec);
    for (const auto& [name, text] : files) {
      if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(text.size())) != 0) {
        mj_deleteVFS(vfs.get());
        throw std::runtime_error("MuJoCo: cannot make the in-memory file " + name);
      }
      std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name.c_str())], text.data(), text.size());
    }
    char error[1000] = "";
    model_ = mj_loadXML(files.front().first.c_str(), vfs.get(), error, sizeof(error));
    mj_deleteVFS(vfs.get());
    if (model_ == nullptr) throw std::runtime_error(std::string("MuJoCo: ") + error);
    data_ = mj_makeData(model_);
    if (model_->nq != 4 * spec.n || model_->nv != 3 * spec.n) throw std::runtime_error("MuJoCo: unexpected nq/nv");
    // Ball joint positions: the rotation relative to the parent, as a quaternion (w, x, y, z).
    qpos0_.resize(model_->nq);
    for (int k = 0; k < spec.n; ++k) {
      const Eigen::Quaterniond q(spec.relativeRotation(k));
      qpos0_[4 * k] = q.w();
      qpos0_[4 * k + 1] = q.x();
      qpos0_[4 * k + 2] = q.y();
      qpos0_[4 * k + 3] = q.z();
    }
    tip_site_ = mj_name2id(model_, mjOBJ_SITE, "tip");
    reset();
  }
  ~MujocoSystem() override {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }

  void reset() override {
    mj_resetData(model_, data_);
    for (int i = 0; i < model_->nq; ++i) data_->qpos[i] = qpos0_[i];
    mj_forward(model_, data_);
  }
  void step() override { mj_step(model_, data_); }
  bool healthy() const override {
    // mj_step resets the state when it meets a bad acceleration (and warns): count those.
    for (int i = 0; i < mjNWARNING; ++i)
      if (data_->warning[i].number > 0) return false;
    return true;
  }
  std::string note() const override {
    return lastWarning().empty() ? std::string() : "MuJoCo warned: " + lastWarning();
  }
  double energy() override {
    model_->opt.enableflags |= mjENBL_ENERGY;  // MuJoCo computes the energies only with this flag
    mj_forward(model_, data_);
    model_->opt.enableflags &= ~mjENBL_ENERGY;
    return data_->energy[0] + data_->energy[1];
  }
  Eigen::Vector3d tip() override {
    mj_forward(model_, data_);
    const mjtNum* p = data_->site_xpos + 3 * tip_site_;
    return {p[0], p[1], p[2]};
  }

 private:
  ChainSpec spec_;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  std::vector<double> qpos0_;
  int tip_site_ = -1;
};

}  // namespace

std::unique_ptr<System> makeMujoco(const ChainSpec& spec) { return std::make_unique<MujocoSystem>(spec); }

}  // namespace bench
