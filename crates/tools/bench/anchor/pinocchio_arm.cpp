// The Pinocchio anchor for `cargo xtask bench --anchors`: the same arm
// as Kinolab's (read from the description `arm_model` prints: joints,
// masses, tool, state), timed on the calls the lab's kernels are compared
// with. Built only when the `pin` wheel and Eigen's headers are installed;
// never part of the lab.
//
// usage: pinocchio_arm MODEL.txt
// prints: check lines (tool position, Jacobian norm, torques, the mass
// matrix's diagonal, forward accelerations) and, per kernel,
// "time <name> <median ns per call>".

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/kinematics.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea.hpp>

namespace pin = pinocchio;

static pin::SE3 read_placement(std::istringstream &in) {
  Eigen::Matrix3d r;
  Eigen::Vector3d t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) in >> r(i, j);
  in >> t(0) >> t(1) >> t(2);
  return pin::SE3(r, t);
}

// Joints whose axis is a coordinate axis get Pinocchio's specialised joint
// types (as its URDF parser does); any other axis the general one.
static pin::JointIndex add_joint(pin::Model &model, pin::JointIndex parent, const std::string &kind,
                                 const Eigen::Vector3d &axis, const pin::SE3 &placement,
                                 const std::string &name) {
  const double e = 1e-12;
  if (kind == "revolute") {
    if ((axis - Eigen::Vector3d::UnitX()).norm() < e)
      return model.addJoint(parent, pin::JointModelRX(), placement, name);
    if ((axis - Eigen::Vector3d::UnitY()).norm() < e)
      return model.addJoint(parent, pin::JointModelRY(), placement, name);
    if ((axis - Eigen::Vector3d::UnitZ()).norm() < e)
      return model.addJoint(parent, pin::JointModelRZ(), placement, name);
    return model.addJoint(parent, pin::JointModelRevoluteUnaligned(axis), placement, name);
  }
  return model.addJoint(parent, pin::JointModelPrismaticUnaligned(axis), placement, name);
}

template <typename F> static double median_ns(F f, int calls) {
  std::vector<double> batches;
  for (int b = 0; b < 31; ++b) {
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < calls; ++i) f();
    auto stop = std::chrono::steady_clock::now();
    batches.push_back(std::chrono::duration<double, std::nano>(stop - start).count() / calls);
  }
  std::sort(batches.begin(), batches.end());
  return batches[batches.size() / 2];
}

int main(int argc, char **argv) {
  if (argc < 2) {
    std::cerr << "usage: pinocchio_puma MODEL.txt\n";
    return 2;
  }
  std::ifstream file(argv[1]);
  pin::Model model;
  pin::JointIndex parent = 0;
  pin::SE3 tool = pin::SE3::Identity();
  Eigen::VectorXd q, qd, qdd;
  std::string line;
  int n = 0;
  while (std::getline(file, line)) {
    std::istringstream in(line);
    std::string kind;
    in >> kind;
    if (kind == "revolute" || kind == "prismatic") {
      Eigen::Vector3d axis;
      in >> axis(0) >> axis(1) >> axis(2);
      pin::SE3 placement = read_placement(in);
      parent = add_joint(model, parent, kind, axis, placement, "j" + std::to_string(++n));
    } else if (kind == "inertia") {
      double m, c[3], i[6];
      in >> m >> c[0] >> c[1] >> c[2];
      for (double &v : i) in >> v;
      Eigen::Matrix3d inertia;
      inertia << i[0], i[1], i[2], i[1], i[3], i[4], i[2], i[4], i[5];
      model.inertias[parent] = pin::Inertia(m, Eigen::Vector3d(c[0], c[1], c[2]), inertia);
    } else if (kind == "tool") {
      tool = read_placement(in);
    } else if (kind == "q" || kind == "qd" || kind == "qdd") {
      std::vector<double> v;
      double x;
      while (in >> x) v.push_back(x);
      Eigen::VectorXd read = Eigen::Map<Eigen::VectorXd>(v.data(), v.size());
      (kind == "q" ? q : kind == "qd" ? qd : qdd) = read;
    }
  }
  if (model.nq == 0 || q.size() != model.nq || qd.size() != model.nv || qdd.size() != model.nv) {
    std::cerr << "pinocchio_arm: the model file has no joints or a state of the wrong length\n";
    return 2;
  }
  model.gravity.linear(Eigen::Vector3d(0.0, 0.0, -9.81));
  const pin::FrameIndex frame =
      model.addFrame(pin::Frame("tool", parent, 0, tool, pin::OP_FRAME));
  pin::Data data(model);
  pin::Data::Matrix6x joint_j = pin::Data::Matrix6x::Zero(6, model.nv);
  pin::Data::Matrix6x frame_j = pin::Data::Matrix6x::Zero(6, model.nv);

  pin::forwardKinematics(model, data, q);
  pin::updateFramePlacement(model, data, frame);
  pin::computeFrameJacobian(model, data, q, frame, pin::LOCAL_WORLD_ALIGNED, frame_j);
  const Eigen::Vector3d p = data.oMf[frame].translation();
  std::printf("check tool %.15f %.15f %.15f\n", p(0), p(1), p(2));
  std::printf("check jacobian_norm %.15f\n", frame_j.norm());
  const Eigen::VectorXd tau = pin::rnea(model, data, q, qd, qdd);
  std::printf("check tau");
  for (int i = 0; i < tau.size(); ++i) std::printf(" %.15f", tau(i));
  pin::crba(model, data, q);
  std::printf("\ncheck mass_diagonal");
  for (int i = 0; i < model.nv; ++i) std::printf(" %.15f", data.M(i, i));
  const Eigen::VectorXd forward = pin::aba(model, data, q, qd, qdd);
  std::printf("\ncheck forward");
  for (int i = 0; i < forward.size(); ++i) std::printf(" %.15f", forward(i));
  std::printf("\n");

  volatile double sink = 0.0;
  const int calls = 20000;
  std::printf("time fk %.3f\n", median_ns(
                                         [&] {
                                           pin::forwardKinematics(model, data, q);
                                           pin::updateFramePlacement(model, data, frame);
                                           sink = sink + data.oMf[frame].translation()(0);
                                         },
                                         calls));
  std::printf("time jacobian %.3f\n", median_ns(
                                               [&] {
                                                 pin::computeJointJacobian(model, data, q, parent, joint_j);
                                                 sink = sink + joint_j(0, 0);
                                               },
                                               calls));
  std::printf("time jacobian_frame %.3f\n",
              median_ns(
                  [&] {
                    pin::computeFrameJacobian(model, data, q, frame, pin::LOCAL_WORLD_ALIGNED, frame_j);
                    sink = sink + frame_j(0, 0);
                  },
                  calls));
  std::printf("time rnea %.3f\n", median_ns(
                                     [&] {
                                       pin::rnea(model, data, q, qd, qdd);
                                       sink = sink + data.tau(0);
                                     },
                                     calls));
  std::printf("time gravity %.3f\n", median_ns(
                                        [&] {
                                          pin::computeGeneralizedGravity(model, data, q);
                                          sink = sink + data.g(0);
                                        },
                                        calls));
  std::printf("time crba %.3f\n", median_ns(
                                     [&] {
                                       pin::crba(model, data, q);
                                       sink = sink + data.M(0, 0);
                                     },
                                     calls));
  std::printf("time aba %.3f\n", median_ns(
                                    [&] {
                                      pin::aba(model, data, q, qd, qdd);
                                      sink = sink + data.ddq(0);
                                    },
                                    calls));
  return 0;
}
