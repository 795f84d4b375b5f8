"""Random elastic laws, volume loads and edge cracks for the random-scene
scripts (scripts/random_scenes --laws, scripts/fuzz_inputs classes
material-law and inadmissible-law). Standard library only.

Admissible draws (every one must be accepted by bilayer):
    isotropic(rng, E)        {"Young's modulus", "Poisson's ratio"}: nu in
                             [-0.3, 0.45]
    orthotropic(rng, E, plane_stress)
                             E_1, E_2, E_3 within a decade of E, G_12 in
                             [0.05, 0.6] sqrt(E_1 E_2) / 2, nu_12, nu_13,
                             nu_23 drawn in (-0.9, 0.9) sqrt(E_i/E_j) until the
                             3-D compliance is positive definite with margin
                             (det of the Poisson matrix >= 0.05), Orientation
                             angle in [-180, 360]
    anisotropic(rng, E)      Stiffness = Q diag(l) Q^T in Voigt form (s11, s22,
                             s12 against e11, e22, 2 e12): eigenvalues l log-
                             uniform in [E/20, E], Q a random rotation of R^3
    law(rng, E, plane_stress, weights)
                             one of the three, with "Law"; the entries of a
                             Materials/Layer k (or its Omega-/Omega+) section
    reference_shear(entries) a shear modulus of the law (for load scales)
    volume_terms(rng, const) an expression pair / triple in x, y scaled by
                             the constant CONST (loads scale with it)
    thermal_expansion(rng, law)
                             a Thermal expansion of the law: one number alpha
                             in [0.5, 3] 1e-5/K, or (orthotropic) alpha_1 in
                             [-0.2, 3], alpha_2, alpha_3 in [0.5, 4] 1e-5/K,
                             or (anisotropic) alpha_11, alpha_22 in [0.5, 3],
                             alpha_12 in [-1, 1] 1e-5/K
    thermal(rng, s, layers, const)
                             thermal entries on top of the settings S (their
                             Law entries drawn): per layer a Thermal expansion
                             (70 %), per side sometimes one of its own (always
                             where the layer's three numbers do not fit the
                             side's isotropic law, sometimes 0); a Loads/
                             Temperature change CONST (constant) or CONST (1 +
                             a x + b y) (linear), or none (15 %); returns
                             (tags, dT text or None, value of CONST in
                             [10, 60] K with either sign)

Inadmissible draws, each with the entry its refusal must name:
    inadmissible(rng) -> (settings {"Section/Entry": value}, names [str],
                          description)
"""
import math

ENTRY = "Materials/Layer %d/%s"
SIDES = ["Omega-", "Omega+"]
LAWS = ["isotropic", "orthotropic", "anisotropic"]


def poisson_det(E1, E2, E3, n12, n13, n23):
    """1 - nu12 nu21 - nu23 nu32 - nu13 nu31 - 2 nu21 nu32 nu13 (nu_ji =
    nu_ij E_j / E_i): positive iff the 3-D compliance of positive moduli is
    positive definite (with the 2x2 minors)."""
    n21, n31, n32 = n12 * E2 / E1, n13 * E3 / E1, n23 * E3 / E2
    return 1 - n12 * n21 - n23 * n32 - n13 * n31 - 2 * n21 * n32 * n13


def isotropic(rng, E):
    return {"Young's modulus": "%.4g" % E, "Poisson's ratio": "%.3f" % rng.uniform(-0.3, 0.45)}


def orthotropic(rng, E, plane_stress=False):
    """Admissible orthotropic constants around the modulus E."""
    while True:
        E1, E2, E3 = (E * 10 ** rng.uniform(-0.5, 0.5) for _ in range(3))
        n12 = rng.uniform(-0.9, 0.9) * math.sqrt(E1 / E2) * 0.6
        n13 = rng.uniform(-0.9, 0.9) * math.sqrt(E1 / E3) * 0.6
        n23 = rng.uniform(-0.9, 0.9) * math.sqrt(E2 / E3) * 0.6
        # Round first, then test what bilayer will read.
        vals = [float("%.4g" % v) for v in (E1, E2, E3, n12, n13, n23)]
        if plane_stress:
            ok = 1 - vals[3] ** 2 * vals[1] / vals[0] > 0.05
        else:
            ok = poisson_det(*vals) > 0.05 and all(
                1 - a * a * q > 0.05 for a, q in ((vals[3], vals[1] / vals[0]),
                                                  (vals[4], vals[2] / vals[0]),
                                                  (vals[5], vals[2] / vals[1])))
        if ok:
            break
    G = 0.5 * math.sqrt(vals[0] * vals[1]) * rng.uniform(0.05, 0.6)
    return {"E_1": "%.4g" % vals[0], "E_2": "%.4g" % vals[1], "E_3": "%.4g" % vals[2],
            "nu_12": "%.4g" % vals[3], "nu_13": "%.4g" % vals[4], "nu_23": "%.4g" % vals[5],
            "G_12": "%.4g" % G, "Orientation angle": "%.2f" % rng.uniform(-180, 360)}


def rotation3(rng):
    """A random rotation of R^3 (a unit quaternion)."""
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q))
    a, b, c, d = (x / n for x in q)
    return [[a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
            [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
            [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]]


def det3(C):
    return (C[0][0] * (C[1][1] * C[2][2] - C[1][2] * C[2][1])
            - C[0][1] * (C[1][0] * C[2][2] - C[1][2] * C[2][0])
            + C[0][2] * (C[1][0] * C[2][1] - C[1][1] * C[2][0]))


def stiffness_text(C):
    """C11, C12, C16, C22, C26, C66 of a symmetric 3x3 Voigt matrix."""
    return ", ".join("%.6g" % v for v in (C[0][0], C[0][1], C[0][2], C[1][1], C[1][2], C[2][2]))


def anisotropic(rng, E):
    """A random symmetric positive definite in-plane stiffness."""
    while True:
        Q = rotation3(rng)
        lam = [E * 10 ** rng.uniform(-1.3, 0) for _ in range(3)]
        C = [[sum(Q[i][k] * lam[k] * Q[j][k] for k in range(3)) for j in range(3)]
             for i in range(3)]
        text = stiffness_text(C)
        v = [float(t) for t in text.split(",")]
        R = [[v[0], v[1], v[2]], [v[1], v[3], v[4]], [v[2], v[4], v[5]]]
        if v[0] > 0 and v[0] * v[3] - v[1] ** 2 > 0 and det3(R) > 1e-6 * max(lam) ** 3:
            return {"Stiffness": text}


def law(rng, E, plane_stress=False, weights=(1, 1, 1)):
    """A random admissible law: its entries with "Law"."""
    name = rng.choices(LAWS, weights=weights)[0]
    entries = {"isotropic": lambda: isotropic(rng, E),
               "orthotropic": lambda: orthotropic(rng, E, plane_stress),
               "anisotropic": lambda: anisotropic(rng, E)}[name]()
    entries["Law"] = name
    return entries


def reference_shear(entries):
    """A shear modulus of a law (its entries): mu, G_12 or C66."""
    name = entries.get("Law", "isotropic")
    if name == "isotropic":
        return float(entries["Young's modulus"]) / (2 * (1 + float(entries["Poisson's ratio"])))
    if name == "orthotropic":
        return float(entries["G_12"])
    v = [float(t) for t in entries["Stiffness"].split(",")]
    return min(v[5], v[0], v[3])


# Smooth profiles in x and y (no zero over the whole domain).
PROFILES = ["1", "(-1)", "x", "(-y)", "(1 - x*x)", "sin(3*y)", "(x + y)", "cos(2*x)",
            "x*y", "(1 + 0.5*x)"]


def volume_terms(rng, const, n):
    """N ';'-separated expressions, each a random multiple of CONST times a
    profile (or 0; never all 0)."""
    comps = ["%.3g*%s*%s" % (rng.uniform(0.2, 2), const, rng.choice(PROFILES))
             if rng.random() < 0.7 else "0" for _ in range(n)]
    if all(c == "0" for c in comps):
        comps[0] = const
    return "; ".join(comps)


def thermal_expansion(rng, law_name):
    """A random Thermal expansion text of the law LAW_NAME [1/K]."""
    if law_name == "isotropic" or rng.random() < 0.3:
        return "%.3g" % (rng.uniform(0.5, 3) * 1e-5)
    if law_name == "orthotropic":
        a = [rng.uniform(-0.2, 3), rng.uniform(0.5, 4), rng.uniform(0.5, 4)]
    else:
        a = [rng.uniform(0.5, 3), rng.uniform(0.5, 3), rng.uniform(-1, 1)]
    return ", ".join("%.3g" % (v * 1e-5) for v in a)


def thermal(rng, s, layers=(1, 2), const="dT0"):
    """Thermal expansions and a temperature change on top of the settings S
    (in place). Returns (tags, the Temperature change text or None, the
    value of CONST)."""
    tags = []
    for k in layers:
        sec = "Materials/Layer %d/" % k
        layer_law = s.get(sec + "Law", "isotropic")
        three = False
        if rng.random() < 0.7:
            text = thermal_expansion(rng, layer_law)
            s[sec + "Thermal expansion"] = text
            three = "," in text
            tags.append("a%d" % k)
        for side in SIDES:
            law_here = s.get(sec + side + "/Law", layer_law)
            # The layer's three numbers do not fit an isotropic side.
            must = three and law_here == "isotropic"
            if must or rng.random() < 0.15:
                s[sec + side + "/Thermal expansion"] = (
                    thermal_expansion(rng, law_here) if must or rng.random() < 0.8 else "0")
                tags.append("a%d%s" % (k, side[-1]))
    value = rng.choice([-1, 1]) * rng.uniform(10, 60)
    kind = rng.random()
    if kind < 0.15:
        return tags, None, value
    if kind < 0.55:
        return tags + ["dT"], const, value
    return tags + ["dT(x,y)"], "%s*(1 %+.2f*x %+.2f*y)" % (
        const, rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)), value


# --------------------------------------------------------------------------
# Inadmissible values: each (settings, names, what) with NAMES the strings
# one of which the refusal line must contain (the entry it names).

def inadmissible(rng):
    """One inadmissible material or load value for partial_closure.prm-like
    scenes, with the entry names the one-line refusal must contain."""
    k = rng.choice([1, 2])
    side = rng.choice(["", "Omega-/", "Omega+/"])
    sec = "Materials/Layer %d/%s" % (k, side)
    kind = rng.choice(["stiffness-indefinite", "stiffness-shear", "stiffness-negative",
                       "stiffness-list", "stiffness-nan", "ortho-G", "ortho-E", "ortho-nu12",
                       "ortho-det", "ortho-nu12-stress", "ortho-angle", "iso-incompressible",
                       "iso-nu", "body-nonfinite", "eigen-nonfinite", "body-list",
                       "eigen-list", "law-name", "plane-state", "thermal-list",
                       "temperature-nonfinite"])
    s, names = {}, []
    if kind.startswith("stiffness"):
        s[sec + "Law"] = "anisotropic"
        value = {"stiffness-indefinite": "100, 120, 0, 100, 0, 30",
                 "stiffness-shear": "100, %g, 60, 100, 0, 30" % rng.uniform(0, 20),
                 "stiffness-negative": "%g, 10, 0, 100, 0, 30" % -rng.uniform(0, 100),
                 "stiffness-list": rng.choice(["1, 2, 3, 4, 5", "1, 2, 3, 4, 5, 6, 7",
                                               "1; 2; 3; 4; 5; 6", "a, b, c, d, e, f",
                                               "250, 100, 0, 250, 0,", ""]),
                 "stiffness-nan": rng.choice(["nan, 0, 0, 1, 0, 1", "250, 100, 0, inf, 0, 75",
                                              "1e400, 0, 0, 1, 0, 1"])}[kind]
        if kind == "stiffness-list" and value == "" and side:
            value = "1, 2"      # empty means "as the layer" on a side
        s[sec + "Stiffness"] = value
        names = ["Stiffness"]
    elif kind.startswith("ortho"):
        s[sec + "Law"] = "orthotropic"
        if kind == "ortho-G":
            s[sec + "G_12"] = rng.choice(["0", "-1", "-1e-300"])
            names = ["G_12"]
        elif kind == "ortho-E":
            e = rng.choice(["E_1", "E_2", "E_3"])
            s[sec + e] = rng.choice(["0", "-200", "nan", "-inf"])
            names = [e]
            if e == "E_3":
                s["Materials/Layer %d/Plane state" % k] = "plane strain"
        elif kind == "ortho-nu12":
            s[sec + "E_1"], s[sec + "E_2"] = "10", "40"
            s[sec + "nu_12"] = "%.3g" % (rng.choice([-1, 1]) * rng.uniform(0.5, 2))
            names = ["nu_12"]
        elif kind == "ortho-nu12-stress":
            s["Materials/Layer %d/Plane state" % k] = "plane stress"
            s[sec + "nu_12"] = "%.3g" % (rng.choice([-1, 1]) * rng.uniform(1.0, 3))
            names = ["nu_12"]
        elif kind == "ortho-det":
            # Equal moduli: det = 1 - 3 nu^2 - 2 nu^3 <= 0 from nu = 0.5 on
            # (the incompressible limit) and for nu <= -1.
            nu = rng.choice([0.5, 0.5, 0.6, 0.7])
            s["Materials/Layer %d/Plane state" % k] = "plane strain"
            for e in ("nu_12", "nu_13", "nu_23"):
                s[sec + e] = "%g" % nu
            names = ["nu_12"]
        else:
            s[sec + "Orientation angle"] = rng.choice(["361", "-361", "1e9", "nan", "inf"])
            names = ["Orientation angle"]
    elif kind.startswith("iso"):
        s[sec + "Law"] = "isotropic"
        if kind == "iso-incompressible":
            s["Materials/Layer %d/Plane state" % k] = "plane strain"
            s[sec + "Poisson's ratio"] = rng.choice(["0.5", "0.50000000000000001", "0.6"])
        else:
            s[sec + "Poisson's ratio"] = rng.choice(["-1", "-1.5", "nan", "inf"])
        names = ["Poisson's ratio"]
    elif kind in ("body-nonfinite", "eigen-nonfinite", "body-list", "eigen-list"):
        k = 1       # layer 2 may be absent in some files
        entry = "Body force" if kind.startswith("body") else "Eigenstrain"
        n = 2 if entry == "Body force" else 3
        if kind.endswith("nonfinite"):
            bad = rng.choice(["1/(x-x)", "log(x-10)", "sqrt(-1-x*x)", "exp(1e5)", "1e308*1e308",
                              "nan", "inf", "0/0"])
            comps = ["0"] * n
            comps[rng.randrange(n)] = bad
        else:
            comps = ["0"] * rng.choice([m for m in (1, 2, 3, 4) if m != n])
        s["Loads/Layer %d/%s" % (k, entry)] = "; ".join(comps)
        names = [entry]
    elif kind == "thermal-list":
        # Malformed alpha lists: a count that does not fit the law, no
        # number, not finite (refused when read, even without a
        # temperature change).
        name = rng.choice(LAWS)
        s[sec + "Law"] = name
        if name == "isotropic":
            value = rng.choice(["1e-5, 2e-5", "1e-5, 1e-5, 1e-5", "hot", "1e-5; 2e-5", "nan",
                                "inf", "-inf", "1e400", "1e-5,,"])
        else:
            value = rng.choice(["1e-5, 2e-5", "1e-5, 2e-5, 3e-5, 4e-5", "1e-5,, 2e-5",
                                "a, b, c", "nan, 0, 0", "1e-5, inf, 0", "1e-5; 2e-5; 3e-5",
                                "1e-5, 2e-5, 1e999"])
        s[sec + "Thermal expansion"] = value
        if rng.random() < 0.5:
            s["Loads/Temperature change"] = "%.3g" % rng.uniform(-50, 50)
        names = ["Thermal expansion"]
    elif kind == "temperature-nonfinite":
        # Refused whether or not a material expands (all coefficients 0
        # by default).
        s["Loads/Temperature change"] = rng.choice(
            ["0/0", "log(x-100)", "1/(x-x)", "sqrt(-1-x*x)", "exp(1e5)", "1e308*1e308",
             "nan", "inf", "log(x-10) + y", "20*(1 + 0/0*y)"])
        if rng.random() < 0.5:
            s["Materials/Layer %d/Thermal expansion" % rng.choice([1, 2])] = "1.2e-5"
        names = ["Temperature change"]
    elif kind == "law-name":
        s[sec + "Law"] = rng.choice(["Orthotropic", "transversely isotropic", "aniso", "1", "nan"])
        names = ["Law"]
    else:
        s["Materials/Layer %d/Plane state" % k] = rng.choice(["plane", "axisymmetric",
                                                             "plane-stress", "3d"])
        names = ["Plane state"]
    return s, names, kind + (" (" + side.rstrip("/") + ")" if side and kind.startswith(
        ("stiffness", "ortho", "iso", "law", "thermal-list")) else "")
