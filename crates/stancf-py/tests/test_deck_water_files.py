"""A MoorDyn deck's wave and current files from Python: a regular wave
given as MoorDyn's elevation record (`WaveKin 3`) is the wave given in
TOML, and a steady current given as MoorDyn's dynamic profile
(`Currents 2`) is the steady profile (`Currents 1`), docs/method.md
§12.1 (W2c)-(W2d), (W9a)."""

import math

import numpy as np

import stancf

DECK = """MoorDyn v2 deck: a line in waves and a current
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI   Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2) (-) (-)    (-)     (-)
rope       0.08    8.0        5.0E7      -0.8        0    1.2    1.0    0.01    0.5
---------------------- POINT PROPERTIES -----------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -80     0.0     -50.0    0      0       0      0
2     Fixed     0.0     0.0     -5.0     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     rope        1        2         92        12      -
---------------------- OPTIONS --------------------------------------
50            WtrDpth              water depth (m)
{options}------------------------- need this line ----------------------------
"""

ANALYSIS = """[analysis]
type = "dynamic"
time_scheme = "galerkin"
time_step = 0.1
duration = 2.0
"""


def tensions(folder, options, files, water=""):
    folder.mkdir()
    (folder / "deck.txt").write_text(DECK.format(options=options))
    for name, text in files.items():
        (folder / name).write_text(text)
    scenario = folder / "run.toml"
    scenario.write_text(f'[system]\nmoordyn = "deck.txt"\n{water}{ANALYSIS}')
    res = stancf.run(stancf.Scenario.from_file(scenario), out=folder / "out")
    rows = np.genfromtxt(res.directory / "tensions.csv", delimiter=",", names=True, dtype=None)
    return np.array([float(r["tension"]) for r in rows])


def test_a_decks_elevation_record_and_dynamic_current_are_the_toml_wave_and_steady_current(
    tmp_path,
):
    omega = 2.0 * math.pi / 15.0
    record = "".join(
        f"{0.25 * i} {1.5 * math.sin(omega * 0.25 * i)}\n" for i in range(61)
    )
    steady = "h\nh\nh\n-50 0.3 0 0\n0 0.9 0 0\n"
    dynamic = "h\nh\nh\nh\n-50 0\n\n0 0.3 0.9\n100 0.3 0.9\n"
    from_files = tensions(
        tmp_path / "files",
        "3 WaveKin\n2 Currents\n",
        {"wave_elevation.txt": record, "current_profile_dynamic.txt": dynamic},
    )
    in_toml = tensions(
        tmp_path / "toml",
        "1 Currents\n",
        {"current_profile.txt": steady},
        "[[water.waves]]\namplitude = 1.5\nperiod = 15.0\nphase = 90.0\n",
    )
    # Equal equations to round-off: the Newton iterations stop within
    # their tolerance, 1e-10 of the line's length, EA / l = 6.5e6 N/m.
    newton = 1e-10 * 92.0 * 5.0e7 / (92.0 / 12.0)
    assert np.max(np.abs(from_files - in_toml)) < newton
    assert np.ptp(in_toml) > 100.0
