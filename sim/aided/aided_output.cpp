#include "sim/aided/aided_output.hpp"

#include <cmath>

namespace sinsim::sim::aided {

void writeCsvNumber(std::FILE* f, const char* fmt, double v) {
  std::fputc(',', f);
  if (std::isfinite(v)) std::fprintf(f, fmt, v);
}

void writeFilterHeader(std::FILE* f) {
  std::fputs(
      "t_s,north_m,east_m,down_m,vn_mps,ve_mps,vd_mps,psi_n_rad,psi_e_rad,psi_d_rad,"
      "sigma_north_m,sigma_east_m,sigma_down_m,sigma_vn_mps,sigma_ve_mps,sigma_vd_mps,"
      "sigma_psi_n_rad,sigma_psi_e_rad,sigma_psi_d_rad,nees,nis,nis_dof,aiding,outage\n",
      f);
}

void writeFilterRow(std::FILE* f, const FilterEpoch& fe) {
  std::fprintf(f, "%.6f", fe.t);
  for (int i = 0; i < 9; ++i) writeCsvNumber(f, "%.6e", fe.error[i]);
  for (int i = 0; i < 9; ++i) writeCsvNumber(f, "%.6e", fe.sigma[i]);
  writeCsvNumber(f, "%.6e", fe.nees);
  writeCsvNumber(f, "%.6e", fe.nis);
  std::fprintf(f, ",%d,%d,%d\n", fe.nisDof, fe.aiding ? 1 : 0, fe.outage ? 1 : 0);
}

void writeImuHeader(std::FILE* f) {
  std::fputs(
      "t_s,ideal_wx_radps,ideal_wy_radps,ideal_wz_radps,ideal_fx_mps2,ideal_fy_mps2,ideal_fz_mps2,"
      "meas_wx_radps,meas_wy_radps,meas_wz_radps,meas_fx_mps2,meas_fy_mps2,meas_fz_mps2,"
      "ideal_dthx_rad,ideal_dthy_rad,ideal_dthz_rad,ideal_dvx_mps,ideal_dvy_mps,ideal_dvz_mps,"
      "meas_dthx_rad,meas_dthy_rad,meas_dthz_rad,meas_dvx_mps,meas_dvy_mps,meas_dvz_mps\n",
      f);
}

void writeImuRow(std::FILE* f, const nav::ImuSample& ideal, const nav::ImuSample& m) {
  std::fprintf(f, "%.6f", ideal.t);
  for (const nav::ImuSample* s : {&ideal, &m})
    for (const nav::Vec3* v : {&s->dtheta_b, &s->dv_b})
      for (int i = 0; i < 3; ++i) std::fprintf(f, ",%.12e", (*v)[i] / s->dt);
  for (const nav::ImuSample* s : {&ideal, &m})
    for (const nav::Vec3* v : {&s->dtheta_b, &s->dv_b})
      for (int i = 0; i < 3; ++i) std::fprintf(f, ",%.12e", (*v)[i]);
  std::fputc('\n', f);
}

}  // namespace sinsim::sim::aided
