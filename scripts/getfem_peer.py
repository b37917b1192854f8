#!/usr/bin/python3
"""GetFEM as a peer of thinlayer on the SAME discrete contact problem (no mesh).

thinlayer_export_problem (benchmarks/export_problem.cpp, whose header documents every file) writes
a scene's limit-mode problem

    K u = F + Bᵀ r,   g = B u + g_D,   d = g + C r,   Signorini–Coulomb on (r, d) at every node,

with thinlayer's own answer. This script rebuilds that problem in GetFEM 5.4 (python3-getfem,
/usr/bin/python3) from the matrices alone, solves it with GetFEM's basic nodal contact brick with
Coulomb friction (Model.add_basic_contact_brick, unsymmetric Alart–Curnier augmentation,
augmented_version 1) and GetFEM's generalized Newton (Model.solve), from rest and from the bonded
solve, and compares its answer with thinlayer's.

The mapping (GetFEM's conventions read in src/getfem_contact_and_friction_nodal.cc, v5.4.2):

  GetFEM's brick, on one variable U with multipliers λ_N, λ_T, adds Bₙᵀλ_N + Bₜᵀλ_T to the
  equations of U (K U = F + Bₙᵀλ_N + Bₜᵀλ_T at a solution) and enforces, node by node,
      λ_N = min(0, λ_N − r α (Bₙ U − gap))        i.e.  λ_N ≤ 0, Bₙ U ≤ gap, λ_N (Bₙ U − gap) = 0,
      λ_T = P_{B(0, −f λ_N)}(λ_T − r α Bₜ U)      i.e.  |λ_T| ≤ f|λ_N|, λ_T opposite to a slip Bₜ U.
  thinlayer: K u = F + Bᵀ r, r_N ≤ 0, d_N ≤ 0, r_N d_N = 0, |r_T| ≤ f|r_N|, d_T = −ζ r_T.
  So λ = r with no sign change, Bₙ U − gap = d_N, Bₜ U = d_T.

  The springs C = diag(1/(K ℓ)) (a layer's limit law: a spring in series with the stop and with the
  skidding block) are explicit auxiliary DOFs: per row i with 0 < C_i < ∞ an unknown e_i, the part of
  the jump the spring takes (an auxiliary point between the plus side and the stop, e_i its distance
  to the plus side along the row), with stiffness k_i = 1/C_i. Then
      U = (u, e),  K_aug = diag(K, diag(k)),  F_aug = (F, 0),  B_aug = [B, −I_e],  gap = −g_D,N,
  and the e-rows of K_aug U = F_aug + B_augᵀ λ read k_i e_i = −λ_i, so e_i = −C_i r_i and
      B_aug U + g_D = B u + g_D − e = B u + g_D + C r = d:
  the stop and the skidding block act on d exactly as thinlayer's law does. Rows with C_i = 0 (a
  rigid law) get no e_i. A node whose law has no normal stiffness carries nothing (r = 0): it is left
  out of the brick. A row with no tangential interaction (K_T = 0 or f = 0) gets friction
  coefficient 0 (λ_T = 0). GetFEM has no tangential gap: a node with g_D,T ≠ 0 is refused (thinlayer
  refuses interface nodes with a prescribed DOF, so g_D is 0 in every problem it builds), and so is
  a bilateral (bonded) law, which is no contact.

  Starts: from rest (U = 0, λ = 0) and from the bonded solve (every node stuck, d = 0 on both rows,
  the start of thinlayer's sparse Newton), solved in GetFEM too: with the springs in e the stuck rows
  are the linear constraint B_aug U = −g_D (GetFEM's constraint brick with multipliers μ, r = −μ),
  one linear solve, checked against thinlayer's own bonded answer.

  Judging: GetFEM stops when min(‖residual‖₁ / load, ‖ΔU‖₁ / ‖U‖₁) ≤ max_res (its classical Newton;
  the load is 1 here: explicit right-hand sides declare none). Its answer is then judged by
  thinlayer's SPEC residual (core/solvers/contact_problem.h: per body and per interface, the natural
  map, evaluated here in double), and compared with thinlayer's: relative norms of u, r and of the
  supports' reactions, and every node's status (gap / slide / stick, classified as thinlayer does).

Examples (the measurements of docs/studies.md, "GetFEM, the peer on the same discrete problem"; one
thread, medians of 3):
  /usr/bin/python3 scripts/getfem_peer.py --exporter build/thinlayer_export_problem \
      --scene cases/friction_lap/friction_lap.json --sizes 0.25,0.106,0.056
  /usr/bin/python3 scripts/getfem_peer.py --problem /tmp/flap_0.25          # an exported folder
  ... --sizes 1 --check     # the CTest: exit 1 unless GetFEM from the bonded start agrees
"""
import os

# One thread for every BLAS/OpenMP library, before numpy, scipy or getfem load them.
for _variable in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_variable] = "1"

import argparse
import csv
import json
import math
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy.io
import scipy.sparse as sp

import getfem as gf

# --check's thresholds (the issue's: reactions to 1e-8 relative, every status equal; u and r too).
CHECK_RELATIVE = 1e-8
SPEC_TOLERANCE = 1e-10  # thinlayer's default SolverOptions::tolerance


class Unsupported(Exception):
    """A problem this mapping does not cover (said why)."""


# --------------------------------------------------------------------------------------------
# The exported problem
# --------------------------------------------------------------------------------------------

def read_vector(path):
    return np.atleast_1d(np.loadtxt(path, dtype=float))  # "inf" reads as +∞


def read_matrix(path):
    return sp.csr_matrix(scipy.io.mmread(path))


class Problem:
    """thinlayer_export_problem's folder, read back."""

    def __init__(self, folder):
        self.folder = folder
        with open(os.path.join(folder, "problem.json")) as f:
            self.meta = json.load(f)
        with open(os.path.join(folder, "thinlayer.json")) as f:
            self.thinlayer = json.load(f)
        path = lambda name: os.path.join(folder, name)
        self.K = read_matrix(path("K.mtx"))
        self.F = read_vector(path("F.txt"))
        self.B = read_matrix(path("B.mtx"))
        self.gD = read_vector(path("gD.txt"))
        self.C = read_vector(path("C.txt"))
        self.kappa = read_vector(path("kappa.txt"))
        self.body = np.atleast_1d(np.loadtxt(path("body.txt"), dtype=int))
        self.R = read_matrix(path("reactions.mtx"))
        self.R0 = read_vector(path("reactions_offset.txt"))
        with open(path("reactions.csv")) as f:
            self.reaction_names = [(row["support"], row["body"], int(row["component"])) for row in csv.DictReader(f)]
        with open(path("nodes.csv")) as f:
            rows = list(csv.DictReader(f))
        self.interface = np.array([int(r["interface"]) for r in rows])
        self.length = np.array([float(r["length"]) for r in rows])
        self.friction = np.array([float(r["friction"]) for r in rows])
        self.normal_active = np.array([r["normal_active"] == "1" for r in rows])
        self.tangential_active = np.array([r["tangential_active"] == "1" for r in rows])
        self.bilateral = np.array([r["bilateral"] == "1" for r in rows])
        self.K_T = np.array([self.meta["interfaces"][i]["K_T"] for i in self.interface], dtype=float)
        self.u = read_vector(path("u.txt"))
        self.r = read_vector(path("r.txt"))
        self.status = np.atleast_1d(np.loadtxt(path("status.txt"), dtype=int))
        self.u_bonded = read_vector(path("u_bonded.txt"))
        self.r_bonded = read_vector(path("r_bonded.txt"))
        self.n = self.K.shape[0]
        self.m = len(rows)
        assert self.B.shape == (2 * self.m, self.n) and self.F.size == self.n and self.C.size == 2 * self.m

    def reactions(self, u):
        return self.R @ u + self.R0


# --------------------------------------------------------------------------------------------
# thinlayer's yardsticks, in double: the SPEC residual and the statuses
# --------------------------------------------------------------------------------------------

def jump_part(pb, u, r):
    """d = B u + g_D + C r (an infinite compliance's row carries r = 0 and adds nothing)."""
    finite = np.isfinite(pb.C)
    return pb.B @ u + pb.gD + np.where(finite, np.where(finite, pb.C, 0.0) * r, 0.0)


def natural_map(pb, r, d):
    """thinlayer's natural map per row (core/solvers/contact_problem.cpp, natural_map_in)."""
    R = np.empty_like(r)
    rN, rT, dN, dT = r[0::2], r[1::2], d[0::2], d[1::2]
    kN, kT = pb.kappa[0::2], pb.kappa[1::2]
    p = -rN
    R[0::2] = np.where(pb.normal_active, p - np.maximum(0.0, p + kN * dN), rN)
    threshold = np.where(pb.tangential_active, pb.friction * np.maximum(p, 0.0), 0.0)
    R[1::2] = np.where(pb.K_T > 0, rT - np.clip(rT - kT * dT, -threshold, threshold), rT)
    bilateral = pb.bilateral
    R[0::2][bilateral] = np.where(pb.normal_active[bilateral], kN[bilateral] * dN[bilateral], rN[bilateral])
    R[1::2][bilateral] = np.where(pb.K_T[bilateral] > 0, kT[bilateral] * dT[bilateral], rT[bilateral])
    return R


def spec_residual(pb, u, r):
    """thinlayer's SPEC §1.5 residual (max over bodies and interfaces), in double."""
    floor = pb.meta["residual_load_floor"] * np.linalg.norm(pb.F)
    relative = lambda a, b: a / max(b, floor) if max(b, floor) > 0 else a
    contact = pb.B.T @ r
    imbalance = pb.K @ u - pb.F - contact
    bulk = max(relative(np.linalg.norm(imbalance[pb.body == b]),
                        max(np.linalg.norm(pb.F[pb.body == b]), np.linalg.norm(contact[pb.body == b])))
               for b in np.unique(pb.body))
    R = natural_map(pb, r, jump_part(pb, u, r))
    node_of_row = np.repeat(pb.interface, 2)
    interface = max(relative(np.linalg.norm(R[node_of_row == i]), np.linalg.norm(r[node_of_row == i]))
                    for i in np.unique(pb.interface))
    return max(bulk, interface)


def statuses(pb, r):
    """0 gap, 1 slide, 2 stick from σ = r / ℓ (core/solvers/contact_problem.cpp, classify_statuses)."""
    tol = pb.meta["status_tolerance"]
    sN, sT = r[0::2] / pb.length, r[1::2] / pb.length
    out = np.empty(pb.m, dtype=int)
    for i in np.unique(pb.interface):
        on = pb.interface == i
        scale = np.max(np.where(pb.bilateral[on], np.maximum(abs(sN[on]), abs(sT[on])), abs(sN[on])))
        for k in np.flatnonzero(on):
            if pb.bilateral[k]:
                out[k] = 2 if max(abs(sN[k]), abs(sT[k])) > tol * scale else 0
                continue
            pressure = -sN[k]
            if not pressure > tol * scale:
                out[k] = 0
            else:
                out[k] = 1 if abs(sT[k]) >= (1 - tol) * pb.friction[k] * pressure else 2
    return out


# --------------------------------------------------------------------------------------------
# The mapping onto GetFEM's basic contact brick (see the module's docstring)
# --------------------------------------------------------------------------------------------

class Mapping:
    """U = (u, e): the free DOFs and one spring share e_i per compliant row; the brick's rows."""

    def __init__(self, pb):
        if pb.bilateral.any():
            raise Unsupported("a bilateral (bonded) law is no contact: the basic contact brick has none")
        self.contact = np.flatnonzero(pb.normal_active)  # nodes in the brick, in order
        rows = [2 * k + j for k in self.contact for j in (0, 1) if j == 0 or pb.tangential_active[k]]
        self.aux_rows = [i for i in rows if 0 < pb.C[i] < math.inf]  # one e per compliant row
        self.aux_of_row = {i: pb.n + a for a, i in enumerate(self.aux_rows)}
        self.size = pb.n + len(self.aux_rows)
        tangential_offset = pb.gD[2 * self.contact + 1]
        if np.any(tangential_offset != 0):
            raise Unsupported("a tangential jump offset g_D,T != 0: GetFEM's brick has no tangential gap")

        k = np.array([1.0 / pb.C[i] for i in self.aux_rows])
        self.K = sp.block_diag([pb.K, sp.diags(k)], format="csc") if k.size else sp.csc_matrix(pb.K)
        self.F = np.concatenate([pb.F, np.zeros(k.size)])

        def rows_of(component):
            Bc = sp.lil_matrix((self.contact.size, self.size))
            Bc[:, :pb.n] = pb.B[2 * self.contact + component, :]
            for j, node in enumerate(self.contact):
                column = self.aux_of_row.get(2 * node + component)
                if column is not None:
                    Bc[j, column] = -1.0
            return sp.csc_matrix(Bc)

        self.BN, self.BT = rows_of(0), rows_of(1)
        self.gap = -pb.gD[2 * self.contact]
        self.friction = np.where(pb.tangential_active[self.contact], pb.friction[self.contact], 0.0)

    def state(self, pb, u, r):
        """GetFEM's (U, λ_N, λ_T) of thinlayer's (u, r): e_i = −C_i r_i."""
        U = np.concatenate([u, [-pb.C[i] * r[i] for i in self.aux_rows]])
        return U, r[2 * self.contact].copy(), r[2 * self.contact + 1].copy()

    def answer(self, pb, U, lambda_N, lambda_T):
        """thinlayer's (u, r) of GetFEM's state (r = 0 on the nodes left out)."""
        r = np.zeros(2 * pb.m)
        r[2 * self.contact] = lambda_N
        r[2 * self.contact + 1] = lambda_T
        return U[:pb.n].copy(), r


class Clock:
    """Wall and CPU time of this process (one thread: the CPU time is what the load leaves alone)."""

    def __init__(self):
        self.wall, self.cpu = time.perf_counter(), time.process_time()

    def read(self):
        return time.perf_counter() - self.wall, time.process_time() - self.cpu


def spmat(matrix, folder, name):
    """A SciPy matrix as a GetFEM Spmat, through a Matrix Market file (every entry, general)."""
    path = os.path.join(folder, name + ".mtx")
    scipy.io.mmwrite(path, sp.coo_matrix(matrix), symmetry="general", precision=17)
    return gf.Spmat("load", "mm", path)


def bonded_start(pb, mapping, folder):
    """The bonded start in GetFEM: every node stuck (thinlayer's stuck_statuses), i.e. d = 0 on each
    row that carries a force, r = 0 on the others. With the springs in e, d = B_aug U + g_D, so the
    stuck rows are the linear constraint B_s U = −g_D,s: GetFEM's constraint brick with multipliers
    μ (it adds B_sᵀ μ to K U, so K U = F − B_sᵀ μ: r_s = −μ), one linear solve (the model built
    untimed). (u, r, (wall s, CPU s))."""
    stuck_T = pb.tangential_active[mapping.contact]
    Bs = sp.vstack([mapping.BN, mapping.BT[stuck_T, :]], format="csc")
    rows = np.concatenate([2 * mapping.contact, 2 * mapping.contact[stuck_T] + 1])
    md = gf.Model("real")
    md.add_variable("U", mapping.size)
    md.add_explicit_matrix("U", "U", spmat(mapping.K, folder, "K_aug"), 1, 0)
    md.add_explicit_rhs("U", mapping.F)
    md.add_variable("mu", rows.size)
    md.add_constraint_with_multipliers("U", "mu", spmat(Bs, folder, "B_stuck"), -pb.gD[rows])
    clock = Clock()
    md.solve("lsolver", "auto")
    seconds = clock.read()
    r = np.zeros(2 * pb.m)
    r[rows] = -md.variable("mu")
    return md.variable("U")[:pb.n].copy(), r, seconds


class GetfemModel:
    """The discrete problem as a GetFEM model: an explicit matrix brick K_aug on U, an explicit
    right-hand side F_aug, and the basic contact brick with Coulomb friction on (BN, BT, gap)."""

    def __init__(self, mapping, augmentation, folder):
        md = gf.Model("real")
        md.add_variable("U", mapping.size)
        md.add_explicit_matrix("U", "U", spmat(mapping.K, folder, "K_aug"), 1, 0)  # symmetric, not coercive
        md.add_explicit_rhs("U", mapping.F)
        md.add_variable("lambda_N", mapping.contact.size)
        md.add_variable("lambda_T", mapping.contact.size)
        md.add_initialized_data("r", [augmentation])
        md.add_initialized_data("friction", mapping.friction)
        md.add_initialized_data("gap", mapping.gap)
        # (varname_u, multname_n, multname_t, dataname_r, BN, BT, friction, gap, alpha ('' = 1),
        #  augmented_version 1: unsymmetric Alart–Curnier)
        md.add_basic_contact_brick("U", "lambda_N", "lambda_T", "r", spmat(mapping.BN, folder, "BN"),
                                   spmat(mapping.BT, folder, "BT"), "friction", "gap", "", 1)
        self.md = md

    def start(self, U, lambda_N, lambda_T):
        self.md.set_variable("U", U)
        self.md.set_variable("lambda_N", lambda_N)
        self.md.set_variable("lambda_T", lambda_T)

    def solve(self, options):
        """Model.solve: (Newton steps, GetFEM's converged flag, (wall s, CPU s), error or None)."""
        args = ["max_iter", options.max_iter, "max_res", options.max_res, "lsearch", options.lsearch,
                "lsolver", options.lsolver]
        if options.noisy:
            args = ["noisy"] + args
        clock = Clock()
        try:
            steps, converged = self.md.solve(*args)
            error = None
        except Exception as e:  # a GetFEM error (e.g. a singular tangent it cannot perturb away)
            steps, converged, error = -1, 0, str(e).strip().splitlines()[-1]
        return steps, bool(converged), clock.read(), error

    def state(self):
        return self.md.variable("U"), self.md.variable("lambda_N"), self.md.variable("lambda_T")

    def rows(self, variable):
        """The variable's rows in GetFEM's system (its right-hand side, its tangent matrix)."""
        first, size = self.md.interval_of_variable(variable)
        return slice(int(first), int(first) + int(size))


# --------------------------------------------------------------------------------------------
# One problem: GetFEM from each start, against thinlayer
# --------------------------------------------------------------------------------------------

def relative(a, b):
    nb = np.linalg.norm(b)
    return np.linalg.norm(a - b) / nb if nb > 0 else np.linalg.norm(a - b)


def median(values):
    return sorted(values)[len(values) // 2]


def judge(pb, mapping, model, steps, converged, error, options):
    """A GetFEM answer against thinlayer's: its SPEC residual, the relative distances, the statuses."""
    result = {"steps": steps, "getfem_converged": converged, "error": error}
    u, r = mapping.answer(pb, *model.state())
    finite = np.all(np.isfinite(u)) and np.all(np.isfinite(r))
    result["spec_residual"] = spec_residual(pb, u, r) if finite else math.inf
    result["converged"] = converged and result["spec_residual"] <= options.spec_tolerance
    if finite:
        sigma = lambda rr: np.concatenate([rr[0::2] / pb.length, rr[1::2] / pb.length])
        result["u"] = relative(u, pb.u)
        result["r"] = relative(r, pb.r)
        result["sigma"] = relative(sigma(r), sigma(pb.r))
        result["reactions"] = relative(pb.reactions(u), pb.reactions(pb.u))
        s = statuses(pb, r)
        result["status_differ"] = int(np.sum(s != pb.status))
        result["counts"] = [int(np.sum(s == v)) for v in (0, 1, 2)]
    else:
        result.update(u=math.inf, r=math.inf, sigma=math.inf, reactions=math.inf, status_differ=pb.m, counts=None)
    return result


def timed(samples):
    """Median wall and CPU seconds of (wall, CPU) samples, and the samples."""
    return {"time": median([w for w, _ in samples]), "cpu": median([c for _, c in samples]),
            "times": [w for w, _ in samples], "cpus": [c for _, c in samples]}


def peer(folder, options, thinlayer_sample=None):
    """GetFEM on one exported problem: the mapping's own checks, then options.repeat rounds, each a
    thinlayer solve (thinlayer_sample(): (wall s, CPU s), when given: interleaved, so that both see
    the same load), GetFEM's bonded solve, and a GetFEM solve from each start (a fresh model each,
    built untimed). Medians over the rounds; the answers judged are the last round's."""
    pb = Problem(folder)
    mapping = Mapping(pb)
    options = argparse.Namespace(**vars(options))
    if options.augmentation is None:
        options.augmentation = float(np.median(pb.kappa))  # the rows' stiffness: GetFEM's r in force/mm
    if options.max_res is None:
        # GetFEM divides ‖residual‖₁ by the load its source-term bricks declare (‖their rhs‖₁); an
        # explicit rhs declares none (the divisor is then 1): the same relative test, made absolute.
        options.max_res = options.spec_tolerance * float(np.linalg.norm(mapping.F, 1))
    out = {"h": pb.meta["h"], "nodes": pb.m, "n_free": pb.n, "aux": len(mapping.aux_rows),
           "augmentation": options.augmentation, "max_res": options.max_res, "thinlayer": pb.thinlayer}

    # The mapping's checks before any GetFEM solve: thinlayer's answer is an answer of the mapped
    # problem (its SPEC residual, recomputed here; GetFEM's own residual at it).
    out["thinlayer_spec_residual"] = spec_residual(pb, pb.u, pb.r)
    out["thinlayer_status_recomputed_differ"] = int(np.sum(statuses(pb, pb.r) != pb.status))

    samples = {"thinlayer": [], "bonded_solve": [], "rest": [], "bonded": []}
    last = {}
    with tempfile.TemporaryDirectory() as tmp:
        # GetFEM's own residual at thinlayer's answer: its equations of U (force, relative to ‖F‖)
        # and of the multipliers ((λ − projection) / r, mm, relative to ‖B u‖): a wrong sign shows here.
        model = GetfemModel(mapping, options.augmentation, tmp)
        model.start(*mapping.state(pb, pb.u, pb.r))
        model.md.assembly("build_rhs")
        rhs = model.md.rhs()
        out["thinlayer_in_getfem_U"] = np.linalg.norm(rhs[model.rows("U")]) / np.linalg.norm(mapping.F)
        multipliers = np.concatenate([rhs[model.rows(v)] for v in ("lambda_N", "lambda_T")])
        out["thinlayer_in_getfem_lambda"] = np.linalg.norm(multipliers) / np.linalg.norm(pb.B @ pb.u)

        zero = (np.zeros(mapping.size), np.zeros(mapping.contact.size), np.zeros(mapping.contact.size))
        for _ in range(options.repeat):
            if thinlayer_sample:
                samples["thinlayer"].append(thinlayer_sample())
            u_b, r_b, seconds = bonded_start(pb, mapping, tmp)
            samples["bonded_solve"].append(seconds)
            for name in options.starts:
                model = GetfemModel(mapping, options.augmentation, tmp)
                model.start(*(mapping.state(pb, u_b, r_b) if name == "bonded" else zero))
                steps, converged, seconds, error = model.solve(options)
                samples[name].append(seconds)
                last[name] = (model, steps, converged, error)
    out["bonded_vs_thinlayer"] = max(relative(u_b, pb.u_bonded), relative(r_b, pb.r_bonded))
    out["bonded_solve"] = timed(samples["bonded_solve"])
    if not samples["thinlayer"]:  # no interleaving: the exporter's own solves
        t = pb.thinlayer
        samples["thinlayer"] = list(zip(t["solve_time_s"], t.get("call_cpu_s", [math.nan] * len(t["solve_time_s"]))))
    out["thinlayer_time"] = timed(samples["thinlayer"])
    for name, (model, steps, converged, error) in last.items():
        out[name] = judge(pb, mapping, model, steps, converged, error, options)
        out[name].update(timed(samples[name]))
    return out


# --------------------------------------------------------------------------------------------
# Driver: export at each size (thinlayer timed there), then GetFEM, in one run
# --------------------------------------------------------------------------------------------

def load():
    return "load %.2f %.2f %.2f" % os.getloadavg()


def format_start(s):
    mark = "converged" if s["converged"] else ("NOT converged" + (" (%s)" % s["error"][:60] if s["error"] else ""))
    return "%d steps, %.4f s (CPU %.4f s), %s" % (s["steps"], s["time"], s["cpu"], mark)


def samples_text(timing):
    return ", ".join("%.3f/%.3f" % wc for wc in zip(timing["times"], timing["cpus"]))


def print_result(res):
    t, tt, bs = res["thinlayer"], res["thinlayer_time"], res["bonded_solve"]
    print("h = %g mm: %d nodes on S, %d free DOFs, %d spring DOFs; GetFEM r = %.4g, max_res = %.3g" %
          (res["h"], res["nodes"], res["n_free"], res["aux"], res["augmentation"], res["max_res"]))
    print("  mapping checks: thinlayer's answer has SPEC residual %.2e here (its own %.2e), statuses recomputed "
          "differ at %d nodes; GetFEM's residual at thinlayer's answer: U rows %.1e, multiplier rows %.1e "
          "(relative); GetFEM's bonded start vs thinlayer's %.1e" %
          (res["thinlayer_spec_residual"], t["residual"]["value"], res["thinlayer_status_recomputed_differ"],
           res["thinlayer_in_getfem_U"], res["thinlayer_in_getfem_lambda"], res["bonded_vs_thinlayer"]))
    print("  thinlayer: %s, %d steps, %.4f s (CPU %.4f s), residual %.2e, %s; wall/CPU samples %s" %
          (t["method"], t["steps"], tt["time"], tt["cpu"], t["residual"]["value"], t["stop_cause"], samples_text(tt)))
    print("  GetFEM bonded solve: %.4f s (CPU %.4f s); samples %s" % (bs["time"], bs["cpu"], samples_text(bs)))
    for name in ("rest", "bonded"):
        s = res.get(name)
        if s is None:
            continue
        print("  GetFEM from %s: %s; GetFEM's flag %s; SPEC residual %.2e; samples %s" %
              (name, format_start(s), s["getfem_converged"], s["spec_residual"], samples_text(s)))
        print("      vs thinlayer: reactions %.1e, u %.1e, r %.1e, sigma %.1e; statuses differ at %d of %d nodes "
              "(GetFEM gap/slide/stick %s, thinlayer %s)" %
              (s["reactions"], s["u"], s["r"], s["sigma"], s["status_differ"], res["nodes"], s["counts"],
               [t["status_counts"][k] for k in ("gap", "slide", "stick")]))


def print_table(results):
    """One row per size, medians. thinlayer's steps are factorisations, its bonded solve the first of
    them; GetFEM's are Newton steps after its own bonded solve (one more linear solve, timed apart).
    Ratios of wall times, and of CPU times in brackets."""
    print()
    print("| h (mm) | nodes on S | free DOFs | thinlayer: steps, s | GetFEM from bonded: bonded solve s + Newton "
          "steps, s | GetFEM (with its bonded solve) / thinlayer: wall [CPU] | GetFEM from rest | GetFEM vs "
          "thinlayer: reactions, u, r, statuses differing | load (1 min) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for res in results:
        t, tt, bs, b, z = res["thinlayer"], res["thinlayer_time"], res["bonded_solve"], res.get("bonded"), res.get("rest")
        row = ["%g" % res["h"], "%d" % res["nodes"], "%d" % res["n_free"], "%d, %.3f" % (t["steps"], tt["time"])]
        if b:
            row.append("%.3f + %d%s, %.3f" % (bs["time"], b["steps"], "" if b["converged"] else " NOT converged", b["time"]))
            row.append("%.2f [%.2f]" % ((b["time"] + bs["time"]) / tt["time"], (b["cpu"] + bs["cpu"]) / tt["cpu"]))
        else:
            row += ["-", "-"]
        if z:
            row.append("%d steps, %.2f s, %s" % (z["steps"], z["time"], "converged" if z["converged"] else
                                                 "NOT converged" + (": " + z["error"][:50] if z["error"] else "")))
        else:
            row.append("-")
        row.append("%.0e, %.0e, %.0e, %d" % (b["reactions"], b["u"], b["r"], b["status_differ"]) if b else "-")
        row.append(res["load"])
        print("| " + " | ".join(row) + " |")


def check(results):
    """--check: from the bonded start GetFEM converges and agrees with thinlayer."""
    failures = []
    for res in results:
        b = res.get("bonded")
        if b is None:
            failures.append("h = %g: no bonded start was run" % res["h"])
            continue
        if not b["converged"]:
            failures.append("h = %g: GetFEM from the bonded start did not converge (flag %s, SPEC residual %.2e)" %
                            (res["h"], b["getfem_converged"], b["spec_residual"]))
        for key in ("reactions", "u", "r"):
            if not b[key] <= CHECK_RELATIVE:
                failures.append("h = %g: %s differ by %.2e relative (> %g)" % (res["h"], key, b[key], CHECK_RELATIVE))
        if b["status_differ"]:
            failures.append("h = %g: %d statuses differ" % (res["h"], b["status_differ"]))
    for f in failures:
        print("CHECK FAILED: " + f)
    if not failures:
        print("CHECK PASSED: GetFEM from the bonded start agrees with thinlayer at every size "
              "(reactions, u, r to %g relative; every status equal)" % CHECK_RELATIVE)
    return not failures


STARTS = ("rest", "bonded")


def starts_list(text):
    """--starts: the names of STARTS, comma separated, each once; "both" is all of them. Anything else
    is refused with the names allowed (argparse turns the ArgumentTypeError into one line, exit 2)."""
    names = []
    for name in text.split(","):
        expanded = list(STARTS) if name == "both" else [name]
        for start in expanded:
            if start not in STARTS:
                raise argparse.ArgumentTypeError("unknown start %r (expected rest, bonded or both)" % name)
            if start not in names:
                names.append(start)
    return names


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    source = parser.add_argument_group("problems: exported folders, or export them here")
    source.add_argument("--problem", action="append", default=[], help="a thinlayer_export_problem folder")
    source.add_argument("--exporter", help="thinlayer_export_problem to run at each --sizes")
    source.add_argument("--scene", help="the scene file to export")
    source.add_argument("--sizes", help="element sizes along the bondlines, mm (comma separated)")
    source.add_argument("--workdir", help="where to export (default: a temporary folder)")
    parser.add_argument("--repeat", type=int, default=3,
                        help="rounds: each a thinlayer solve (with --sizes), GetFEM's bonded solve and a GetFEM solve "
                             "from each start; medians are kept")
    parser.add_argument("--starts", type=starts_list, default="rest,bonded",
                        help="the starts GetFEM solves from: rest, bonded, both (= rest,bonded) or a comma list "
                             "of rest and bonded (default rest,bonded)")
    parser.add_argument("--lsearch", default="simplest",
                        help="GetFEM's line search: simplest (the default here), basic, systematic, quadratic, or "
                             "default (its Newton with step control)")
    parser.add_argument("--lsolver", default="auto", help="GetFEM's linear solver (auto: MUMPS when built with it)")
    parser.add_argument("--max-iter", type=int, default=50)
    parser.add_argument("--max-res", type=float, default=None,
                        help="GetFEM's stopping value (absolute, see the docstring); default: --spec-tolerance "
                             "times ‖F‖₁, the relative test GetFEM makes when a source-term brick declares its load")
    parser.add_argument("--augmentation", type=float, default=None,
                        help="GetFEM's r (force/mm per mm); default: the median of thinlayer's row stiffnesses kappa")
    parser.add_argument("--spec-tolerance", type=float, default=SPEC_TOLERANCE,
                        help="a GetFEM answer converged: its flag and thinlayer's SPEC residual at most this")
    parser.add_argument("--noisy", action="store_true", help="GetFEM prints its Newton iterations")
    parser.add_argument("--check", action="store_true", help="exit 1 unless GetFEM from the bonded start agrees")
    parser.add_argument("--json", help="write every number to this file")
    options = parser.parse_args()

    print("GetFEM %s, one thread (OMP/OPENBLAS_NUM_THREADS=1); line search %s, linear solver %s; %s" %
          (getattr(gf, "__version__", "5.4"), options.lsearch, options.lsolver, load()))
    results = []
    with tempfile.TemporaryDirectory() as scratch:
        folders = list(options.problem)
        sizes = [float(h) for h in options.sizes.split(",")] if options.sizes else []
        if sizes and not (options.exporter and options.scene):
            parser.error("--sizes needs --exporter and --scene")
        for h in sizes:
            folder = os.path.join(options.workdir or scratch, "h_%g" % h)
            command = [options.exporter, "--scene", options.scene, "--h", "%.17g" % h, "--out", folder, "--repeat", "1"]
            print("$ " + " ".join(command) + "   (" + load() + ")", flush=True)
            if subprocess.run(command).returncode not in (0, 1):  # 1: thinlayer did not converge (still compared)
                print("export failed at h = %g" % h)
                return 2

            def thinlayer_sample(command=command[:-4] + ["--out", os.path.join(scratch, "timing"), "--repeat", "1"]):
                """One more thinlayer solve of the same problem, in its own process (the same mesh)."""
                subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
                with open(os.path.join(scratch, "timing", "thinlayer.json")) as f:
                    t = json.load(f)
                return t["solve_time_s"][0], t["call_cpu_s"][0]

            res = peer(folder, options, thinlayer_sample)
            res["load"] = load()
            print_result(res)
            print("  (%s)" % res["load"], flush=True)
            results.append(res)
        for folder in options.problem:
            res = peer(folder, options)
            res["load"] = load()
            print_result(res)
            results.append(res)
    print_table(results)
    if options.json:
        with open(options.json, "w") as f:
            json.dump(results, f, indent=2, default=float)
    if options.check:
        return 0 if check(results) else 1
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Unsupported as e:
        print("getfem_peer: unsupported problem: %s" % e)
        sys.exit(2)
