#!/usr/bin/env bash
# RABBIT's designed gaits (docs/design.md, "RABBIT"): `walker design` of the five-link biped
# (models/five-link.toml) on level floors of mu0 = 0.6 and 0.3, least specific resistance at
# a speed of at least 0.6 m/s with the swing foot 2 cm clear of the floor at mid-stance and the
# foot held (exact Coulomb friction in stance and at the impact); then the README's animation
# of the mu0 = 0.3 gait, from its fixed point. Writes docs/designs/rabbit-mu0-*.json and
# docs/figures/rabbit.svg; about three minutes of one core.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
cargo build --release -q -p walker-cli
w=target/release/walker
model=models/five-link.toml
contact=(--friction coulomb --impact coulomb)
vary="T_set=0.3:0.8:0.5,beta=0.1:0.4:0.225,th_ref=0:0.5:0.085,kappa=0.1:1.0:0.5,kappa_m=0.1:1.2:0.5"
for mu in 0.6 0.3; do
    "$w" design --model "$model" "${contact[@]}" --set "mu0=$mu" --vary "$vary" \
        --clearance 0.02 --min-speed 0.6 --json > "docs/designs/rabbit-mu0-$mu.json"
done
# The designed parameters (--set) and fixed point (--init) of the mu0 = 0.3 design.
mapfile -t args < <(python3 - docs/designs/rabbit-mu0-0.3.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
names = ["x", "z", "th_s1", "th_f1", "th_torso", "th_f2", "th_s2"]
names += [n + "d" for n in names]
for p in d["parameters"]:
    print("--set"); print(f"{p['name']}={p['value']!r}")
for n, v in zip(names, d["gait"]["fixed_point"]["state_plus"]):
    print("--init"); print(f"{n}={v!r}")
PY
)
"$w" animate --model "$model" "${contact[@]}" --set mu0=0.3 "${args[@]}" --steps 8 \
    -o docs/figures/rabbit.svg
