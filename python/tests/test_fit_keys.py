# SPDX-License-Identifier: BSD-3-Clause
"""The fit result's schema has one description in effect: restitution.fit_data returns the keys and values that
`restitution fit-data --json` writes (docs/fit.md), key for key, so neither can gain or lose one alone."""

import csv
import json

import pytest

import restitution
from conftest import SOURCE_DIR


# What `fit-data --json` writes besides the fit itself: the input echoed back (source, data), the best fit's
# names, with a material its k and the Hertz A a DEM code takes (docs/fit.md), and the SUNDIALS build. Everything else is the
# fit result, whose keys and values restitution.fit_data must give alike.
_CLI_ONLY_FIT_KEYS = {"source", "data", "best_law", "best_end", "k", "dissipative_constant_s", "sundials", "restitution"}
_MATERIAL = {"young_modulus": 7e10, "poisson_ratio": 0.3, "radius": 0.01, "density": 2700.0}


def _measurements(path):
    with open(path) as table:
        rows = list(csv.DictReader(line for line in table if not line.startswith("#")))
    columns = {name: [float(row[name]) for row in rows] for name in rows[0]}
    return columns["v"], columns["eps"], columns.get("sigma")


@pytest.mark.parametrize("with_material", [False, True])
@pytest.mark.parametrize("name", ["rubber_drop.csv", "ice_bridges.csv"])
def test_fit_data_gives_the_keys_and_values_of_the_command_line(name, with_material, cli):
    path = SOURCE_DIR / ("scenes/data" if name == "ice_bridges.csv" else "examples/fit") / name
    material_options = [f"--{key.replace('_', '-')}={value!r}" for key, value in _MATERIAL.items()]
    written = json.loads(cli("fit-data", "--json", str(path), *(material_options if with_material else [])))
    v, eps, sigma = _measurements(path)
    material = restitution.Material(**_MATERIAL) if with_material else None
    module = restitution.fit_data(v, eps, sigma, material=material)

    assert set(module) == set(written) - _CLI_ONLY_FIT_KEYS
    assert {"source", "data"} <= set(written)
    for key in module:
        if key != "fits":
            assert module[key] == written[key], key
    assert len(module["fits"]) == len(written["fits"]) > 0
    for mine, theirs in zip(module["fits"], written["fits"]):
        # The command line writes "message" only when there is one; the dict always has it ("" for none).
        keys = set(mine) - ({"message"} if mine["message"] == "" else set())
        assert keys == set(theirs), mine["law"]
        assert set(mine["residual_tests"]) == set(theirs["residual_tests"]), mine["law"]
        for key in theirs:
            assert mine[key] == theirs[key], (mine["law"], key)
    if with_material:
        assert any("dissipative_constant_s" in fit for fit in module["fits"])
