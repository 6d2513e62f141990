// The diagnosis as a self-contained HTML page (sim/report): per channel the Allan deviation,
// PSD and ACF of the measurement over the model's band with the failing ranges shaded, the
// findings table, and — after an improvement — the before/after curves and misfits.
#pragma once

#include <string>

#include "errormodels/diagnose/diagnose.hpp"
#include "sim/diagnose_nav.hpp"

namespace sinsim {

/// How the user ran the diagnosis, so that the page can say what to run next.
struct DiagnoseCommand {
  std::string base;           ///< "sinsim diagnose DATA <record options>" as typed (no --model)
  std::string model;          ///< the model file diagnosed
  std::string improvedModel;  ///< the improved model written (--add), else empty
};

/// The page's HTML text. Values are shown in deg/s (gyro) and mg (accelerometer). With `nav`
/// (diagnose --nav) a section shows the navigation verdict and the drift curves.
std::string diagnoseReportHtml(const errormodels::diagnose::Diagnosis& d,
                               const errormodels::diagnose::Improvement* improvement = nullptr,
                               const DiagnoseCommand* command = nullptr,
                               const sim::NavVerdict* nav = nullptr);

/// Writes it atomically (report::HtmlPage::write).
void writeDiagnoseReport(const std::string& path, const errormodels::diagnose::Diagnosis& d,
                         const errormodels::diagnose::Improvement* improvement = nullptr,
                         const DiagnoseCommand* command = nullptr,
                         const sim::NavVerdict* nav = nullptr);

}  // namespace sinsim
