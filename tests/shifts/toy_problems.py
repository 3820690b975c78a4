"""Stand-in problems for the shift solvers' building blocks (nodes, grid, local, scp): the same
interface as geardesign.shifts.problem.Problem (nvar, x_sum, x1_on_line, evaluate, evaluate_point),
with pieces and margins written out here so that each optimum is known analytically."""
import math

import numpy as np


class Disk:
    """Maximise x1 + x2 subject to r² − x1² − x2² >= 0: optimum x1 = x2 = r/√2, fun r·√2.
    The margin is written as (r² − x1² − x2²)/(2r) (a distance to the circle near it)."""

    nvar = 2
    x_sum = None

    def __init__(self, r=1.0):
        self.r = r

    def evaluate(self, V, grads=True):
        V = np.atleast_2d(np.asarray(V, dtype=float))
        x1, x2 = V[:, 0], V[:, 1]
        P = (x1 + x2)[None, :]
        M = ((self.r ** 2 - x1 * x1 - x2 * x2) / (2 * self.r))[None, :]
        if not grads:
            return P, M
        GP = np.ones((1, 2, V.shape[0]))
        GM = np.stack([-x1, -x2])[None, :, :] / self.r
        return P, M, GP, GM

    def evaluate_point(self, v):
        x1, x2 = float(v[0]), float(v[1])
        return (np.array([x1 + x2]), np.array([(self.r ** 2 - x1 * x1 - x2 * x2) / (2 * self.r)]),
                np.array([[1.0, 1.0]]), np.array([[-x1, -x2]]) / self.r)


class Triangle:
    """Margins x1 − a, x2 − a and (s − x1 − x2)/√2, each the signed distance to one side of the right
    triangle with legs L = s − 2a along x1 = a and x2 = a: its most central point is the incentre
    (a + ρ, a + ρ), ρ = (L + L − L·√2)/2 (legs plus legs minus hypotenuse, over two). One piece, x1 + x2."""

    nvar = 2
    x_sum = None

    def __init__(self, a=0.0, s=1.0):
        self.a, self.s = a, s

    def inradius(self):
        legs = self.s - 2 * self.a
        return (2 * legs - legs * math.sqrt(2)) / 2

    def _margins(self, x1, x2):
        return np.array([x1 - self.a, x2 - self.a, (self.s - x1 - x2) / math.sqrt(2)])

    def evaluate(self, V, grads=True):
        V = np.atleast_2d(np.asarray(V, dtype=float))
        x1, x2 = V[:, 0], V[:, 1]
        P, M = (x1 + x2)[None, :], self._margins(x1, x2)
        if not grads:
            return P, M
        n = V.shape[0]
        GP = np.ones((1, 2, n))
        GM = np.broadcast_to(np.array([[1.0, 0.0], [0.0, 1.0], [-1 / math.sqrt(2), -1 / math.sqrt(2)]])[:, :, None],
                             (3, 2, n)).copy()
        return P, M, GP, GM

    def evaluate_point(self, v):
        x1, x2 = float(v[0]), float(v[1])
        return (np.array([x1 + x2]), self._margins(x1, x2), np.array([[1.0, 1.0]]),
                np.array([[1.0, 0.0], [0.0, 1.0], [-1 / math.sqrt(2), -1 / math.sqrt(2)]]))
