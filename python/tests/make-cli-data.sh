#!/usr/bin/env bash
# Re-make the command line's JSON outputs that the Python tests compare against (tests/data/).
# Run from anywhere; builds the `walker` binary first.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
cargo build --release -p walker-cli
W="${CARGO_TARGET_DIR:-$root/target}/release/walker"
D=python/tests/data
mkdir -p "$D"
"$W" simulate --scene active-level --mu0 0.4 --t-set 0.3 --omega0 0.8 --max-steps 5 --json > "$D/simulate_active.json"
"$W" simulate --scene passive-slope --mu0 0.19 --phi 0.10 --omega0 0.5 --max-steps 5 --json > "$D/simulate_fig14_fall.json"
"$W" simulate --scene active-level --mu0 0.3 --impact coulomb --friction coulomb --max-steps 4 --json > "$D/simulate_coulomb.json"
"$W" sweep --scene active-level --mu0-from 0.1 --mu0-to 0.4 --mu0-step 0.1 --t-set 0.3 --t-set 0.4 --duration 5 --json > "$D/sweep_active.json"
"$W" sweep --scene passive-slope --mu0-from 0.1 --mu0-to 0.3 --mu0-step 0.1 --phi 0.1 --restart --duration 5 --json > "$D/sweep_passive_restart.json"
"$W" fixed-point --scene active-level --mu0 0.4 --json > "$D/fixed_point_active.json"
"$W" simulate --scene active-level --init th1d=0.7 --init th2d=0.9 --max-steps 3 --json > "$D/simulate_init.json"
"$W" simulate --model models/compass-gait.toml --friction coulomb --impact frictionless --max-steps 5 --json > "$D/simulate_compass_gait.json"
"$W" sweep --scene active-level --param m2 --from 0.8 --to 1.2 --step 0.2 --t-set 0.3 --duration 3 --json > "$D/sweep_m2.json"
"$W" fixed-point --model models/compass-gait.toml --friction coulomb --impact frictionless --json > "$D/fixed_point_compass_gait.json"
