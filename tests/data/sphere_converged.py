"""Richardson extrapolation (order 2, refinement ratio 2) of the sphere
solver at resolutions 4 and 8 (sphere_converged.raw, made by
sphere_converged.sh) -> sphere_converged.json. The estimate of the remaining
error is |x8 - x4|/3 (the extrapolation's own correction)."""
import json, os

here = os.path.dirname(os.path.abspath(__file__))
rows = [json.loads(l) for l in open(os.path.join(here, "sphere_converged.raw"))]
out = {"provenance": "tests/data/sphere_converged.sh: release CLI, resolutions 4 and 8, "
       "Richardson x8 + (x8 - x4)/3", "cases": []}
keys = ["pull_off_load_control", "contact_radius_zero_load", "jump_out_load",
        "jump_out_interference"]
for case in dict.fromkeys(r["case"] for r in rows):
    f = {r["resolution"]: r["facts"] for r in rows if r["case"] == case}
    e = {"mu": f[8]["mu"], "rho": f[8]["rho"]}
    for k in keys:
        a, b = f[4].get(k), f[8].get(k)
        if a is None:
            continue
        e[k] = b + (b - a) / 3.0
        e[k + "_uncertainty"] = abs(b - a) / 3.0
        e[k + "_res4"] = a
        e[k + "_res8"] = b
    out["cases"].append(e)
json.dump(out, open(os.path.join(here, "sphere_converged.json"), "w"), indent=1)
print(json.dumps(out, indent=1))
