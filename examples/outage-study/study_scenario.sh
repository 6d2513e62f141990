# Sourced by examples/outage-study/run.sh and bench/outage_nees/run.sh: the study's scenario,
# car.yaml's drive (without its own error model and seed) with random initial errors, GNSS at
# 1 Hz (1, 1, 2 m) and two 30 s and two 60 s outages.
#   study_scenario NAME TRUTH_MODEL FILTER_MODEL     (prints the YAML; $root = the repository)
study_scenario() {
  cat <<YAML
name: $1
$(sed -n '/^start:/,$p' "$root/scenarios/car.yaml" | grep -v -e '^errors:' -e '^seed:')
errors: $2
initial_errors: {position: {sigma: 3 m}, velocity: {sigma: 0.1 m/s}, attitude: {sigma: [0.3 deg, 0.3 deg, 2 deg]}}
gnss:
  rate: 1 Hz
  position_sigma: [1 m, 1 m, 2 m]
  outages: [{start: 400 s, duration: 30 s}, {start: 800 s, duration: 60 s},
            {start: 1300 s, duration: 30 s}, {start: 1700 s, duration: 60 s}]
filter: {model: $3}
YAML
}
