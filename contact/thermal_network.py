"""A lumped thermal network: nodes with heat capacities, conductances between them and to
fixed-temperature boundaries (MODEL.md §14).

    C dT/dt = Q - L T - G_b (T - T_b)        (eq. 14.1)

L the conductance Laplacian of the free nodes, G_b their conductances to the boundaries
(ambient air, the oil inlet) at T_b. The steady state solves (L + diag(G_b 1)) T = Q + G_b T_b.
Temperatures in kelvin, heat in watts, conductances W/K, capacities J/K.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["ThermalNetwork"]


@dataclass(frozen=True)
class ThermalNetwork:
    """Nodes, links and boundaries of a lumped network (eq. 14.1).

    Attributes
    ----------
    nodes : tuple of str
        Free nodes.
    capacity : ndarray (n,)
        Heat capacities, J/K (> 0).
    links : dict
        {(node, node): conductance W/K} between free nodes (symmetric, >= 0).
    boundary : dict
        {name: temperature K} of the fixed nodes.
    boundary_links : dict
        {(node, boundary name): conductance W/K}.
    """

    nodes: tuple
    capacity: np.ndarray
    links: dict
    boundary: dict
    boundary_links: dict
    _index: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        index = {name: i for i, name in enumerate(self.nodes)}
        if len(index) != len(self.nodes):
            raise ValueError(f"nodes: names must be unique, got {self.nodes!r}")
        capacity = np.asarray(self.capacity, dtype=float)
        if capacity.shape != (len(self.nodes),) or not np.all(np.isfinite(capacity)) or np.any(capacity <= 0):
            raise ValueError(f"capacity: one positive finite value per node, got {self.capacity!r}")
        object.__setattr__(self, "capacity", capacity)
        for (a, b), g in self.links.items():
            if a not in index or b not in index or a == b:
                raise ValueError(f"links: ({a!r}, {b!r}) must join two different nodes of {self.nodes}")
            if not np.isfinite(g) or g < 0:
                raise ValueError(f"links: conductance of ({a!r}, {b!r}) must be finite and >= 0, got {g!r}")
        for (a, b), g in self.boundary_links.items():
            if a not in index or b not in self.boundary:
                raise ValueError(f"boundary_links: ({a!r}, {b!r}) must join a node and a boundary")
            if not np.isfinite(g) or g < 0:
                raise ValueError(f"boundary_links: conductance of ({a!r}, {b!r}) must be finite and >= 0, got {g!r}")
        for name, t in self.boundary.items():
            if not np.isfinite(t) or t <= 0:
                raise ValueError(f"boundary: temperature of {name!r} must be a positive kelvin value, got {t!r}")
        object.__setattr__(self, "_index", index)

    def matrix(self) -> tuple:
        """(A, b): A T = Q + b is the steady balance (eq. 14.1 with dT/dt = 0); A (n, n) W/K,
        b (n,) W."""
        n = len(self.nodes)
        a = np.zeros((n, n))
        b = np.zeros(n)
        for (p, q), g in self.links.items():
            i, j = self._index[p], self._index[q]
            a[i, i] += g
            a[j, j] += g
            a[i, j] -= g
            a[j, i] -= g
        for (p, name), g in self.boundary_links.items():
            i = self._index[p]
            a[i, i] += g
            b[i] += g * self.boundary[name]
        return a, b

    def heat_vector(self, heat: dict) -> np.ndarray:
        """{node: W} as the node order's vector; a name that is no node raises ValueError."""
        q = np.zeros(len(self.nodes))
        for name, value in heat.items():
            if name not in self._index:
                raise ValueError(f"heat: {name!r} is not a node of {self.nodes}")
            q[self._index[name]] += value
        return q

    def steady(self, heat: dict) -> dict:
        """Steady node temperatures {node: K} under the heat {node: W} (eq. 14.1); every node
        must reach a boundary through the links (else the temperatures are unbounded)."""
        a, b = self.matrix()
        try:
            t = np.linalg.solve(a, self.heat_vector(heat) + b)
        except np.linalg.LinAlgError:
            raise ValueError("ThermalNetwork.steady: a node has no path to a boundary (singular network)") from None
        return dict(zip(self.nodes, (float(v) for v in t)))

    def rates(self, temperatures, heat) -> np.ndarray:
        """dT/dt (K/s) of the nodes at ``temperatures`` (n,) K under ``heat`` (n,) W (eq. 14.1)."""
        a, b = self.matrix()
        return (np.asarray(heat, dtype=float) + b - a @ np.asarray(temperatures, dtype=float)) / self.capacity

    def to_boundaries(self, temperatures: dict) -> dict:
        """Heat leaving through each boundary, {boundary: W}, at node ``temperatures`` {node: K}."""
        out = {name: 0.0 for name in self.boundary}
        for (p, name), g in self.boundary_links.items():
            out[name] += g * (temperatures[p] - self.boundary[name])
        return out
