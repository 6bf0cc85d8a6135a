// kin_oracle: pyplcopen's own kinematics (core/kin of its source distribution, header-only
// C++17, Apache-2.0) as an oracle for the closed forms this project derives from D-H tables.
// Built by `make st-engine` beside st_run (Makefile); driven by
// analysis.kinematics.derive.plcopen_oracle.
//
//   kin_oracle < requests > answers
//
// The first line names the mechanism, in pyplcopen's own terms (lengths in mm, angles in rad):
//
//   scara L1 L2 WITHZ                       Scara(link1, link2, with_z)      (kin/scara.h)
//   gantry N S1 .. SN O1 .. ON              CartesianGantry(N, scale, offset) (kin/gantry.h)
//   wrist6r D1 A2 D4 D6                     SphericalWrist6R(...)             (kin/wrist6r.h)
//   chain std|mod N  a alpha d offset  xN   SerialChain (numerical, kin/serial_chain.h)
//
// then one request per line, one answer line each (%.17g numbers):
//
//   fk Q1 .. QN                 -> ok X Y Z                  (scara, gantry)
//                               -> ok X Y Z R00 R01 .. R22   (wrist6r, chain; row-major)
//   ik X Y Z  S1 .. SN          -> ok Q1 .. QN | err CODE    (scara, gantry: seed S)
//   ik X Y Z R00 .. R22  S1 .. SN  STEP  -> ok Q1 .. QN | err CODE   (wrist6r, chain)
//
// CODE is rt::ErrorCode's number. A malformed line answers "bad <reason>" and the driver goes
// on; at most 1,000,000 requests are read.
#include "kin/gantry.h"
#include "kin/scara.h"
#include "kin/serial_chain.h"
#include "kin/wrist6r.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace plcopen::core;

namespace {

bool numbers(std::istringstream &in, std::vector<double> &out, std::size_t n)
{
    out.assign(n, 0.0);
    for(std::size_t i = 0; i < n; ++i) {
        if(!(in >> out[i])) {
            return false;
        }
    }
    return true;
}

void print(const char *head, const double *v, std::size_t n)
{
    std::printf("%s", head);
    for(std::size_t i = 0; i < n; ++i) {
        std::printf(" %.17g", v[i]);
    }
    std::printf("\n");
}

void pose_out(const kin::Pose6 &p)
{
    double v[12];
    for(int i = 0; i < 3; ++i) {
        v[i] = p.position[i];
        for(int j = 0; j < 3; ++j) {
            v[3 + 3 * i + j] = p.rotation[i][j];
        }
    }
    print("ok", v, 12);
}

int translational(kin::Kinematics &k)
{
    const std::size_t n = k.joint_count();
    std::string line;
    std::vector<double> v;
    for(long count = 0; count < 1000000 && std::getline(std::cin, line); ++count) {
        std::istringstream in(line);
        std::string op;
        in >> op;
        if(op == "fk" && numbers(in, v, n)) {
            geom::Vec3 c{};
            if(k.forward(v.data(), n, c) != rt::ErrorCode::ok) {
                std::printf("err fk\n");
                continue;
            }
            const double out[3] = {c.x, c.y, c.z};
            print("ok", out, 3);
        } else if(op == "ik" && numbers(in, v, 3 + n)) {
            std::vector<double> q(n, 0.0);
            const auto code = k.inverse(geom::Vec3{v[0], v[1], v[2]}, v.data() + 3, n, q.data());
            if(code != rt::ErrorCode::ok) {
                std::printf("err %d\n", static_cast<int>(code));
            } else {
                print("ok", q.data(), n);
            }
        } else {
            std::printf("bad request\n");
        }
        std::fflush(stdout);
    }
    return 0;
}

int posed(kin::PoseKinematics &k)
{
    const std::size_t n = k.joint_count();
    std::string line;
    std::vector<double> v;
    for(long count = 0; count < 1000000 && std::getline(std::cin, line); ++count) {
        std::istringstream in(line);
        std::string op;
        in >> op;
        if(op == "fk" && numbers(in, v, n)) {
            kin::Pose6 p;
            k.forward(v.data(), p);
            pose_out(p);
        } else if(op == "ik" && numbers(in, v, 12 + n + 1)) {
            kin::Pose6 p;
            for(int i = 0; i < 3; ++i) {
                p.position[i] = v[i];
                for(int j = 0; j < 3; ++j) {
                    p.rotation[i][j] = v[3 + 3 * i + j];
                }
            }
            std::vector<double> q(n, 0.0);
            const auto code = k.inverse(p, v.data() + 12, v[12 + n], q.data());
            if(code != rt::ErrorCode::ok) {
                std::printf("err %d\n", static_cast<int>(code));
            } else {
                print("ok", q.data(), n);
            }
        } else {
            std::printf("bad request\n");
        }
        std::fflush(stdout);
    }
    return 0;
}

} // namespace

int main()
{
    std::string line;
    if(!std::getline(std::cin, line)) {
        std::fprintf(stderr, "kin_oracle: no mechanism line\n");
        return 2;
    }
    std::istringstream in(line);
    std::string kind;
    in >> kind;
    std::vector<double> v;
    if(kind == "scara" && numbers(in, v, 3)) {
        kin::Scara k(v[0], v[1], v[2] != 0.0);
        return translational(k);
    }
    if(kind == "gantry") {
        std::size_t n = 0;
        if(!(in >> n) || n < 2 || n > 3 || !numbers(in, v, 2 * n)) {
            std::fprintf(stderr, "kin_oracle: gantry N S.. O..\n");
            return 2;
        }
        kin::CartesianGantry k(n, v.data(), v.data() + n);
        return translational(k);
    }
    if(kind == "wrist6r" && numbers(in, v, 4)) {
        kin::SphericalWrist6R k(v[0], v[1], v[2], v[3]);
        return posed(k);
    }
    if(kind == "chain") {
        std::string convention;
        std::size_t n = 0;
        in >> convention >> n;
        if((convention != "std" && convention != "mod") || n < 1 ||
           n > kin::SerialChainMaxJoints || !numbers(in, v, 4 * n)) {
            std::fprintf(stderr, "kin_oracle: chain std|mod N a alpha d offset ...\n");
            return 2;
        }
        kin::SerialChainSpec spec;
        spec.joint_count = n;
        spec.convention =
            convention == "std" ? kin::DhConvention::standard : kin::DhConvention::modified;
        for(std::size_t i = 0; i < n; ++i) {
            spec.links[i].a = v[4 * i];
            spec.links[i].alpha = v[4 * i + 1];
            spec.links[i].d = v[4 * i + 2];
            spec.links[i].theta_offset = v[4 * i + 3];
            spec.links[i].min_position = -1e9;
            spec.links[i].max_position = 1e9;
        }
        kin::SerialChain k(spec);
        return posed(k);
    }
    std::fprintf(stderr, "kin_oracle: unknown mechanism line %s\n", line.c_str());
    return 2;
}
