"""Structured meshes of rectangles, for trying tfem without a mesher.

An :class:`Assembly` collects bodies meshed by :meth:`Assembly.add_grid`
(each with its own nodes, so that bodies meshed against each other stay
separate bodies that contact can join), tags boundary edges chosen by
where their midpoints lie, and hands the arrays to a :class:`tfem.Model`.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

__all__ = ["Assembly"]


class Assembly:
    """Bodies of triangles on tensor grids, with their tagged edges."""

    def __init__(self) -> None:
        self._nodes: list[np.ndarray] = []
        self._triangles: list[np.ndarray] = []
        self._bodies: list[np.ndarray] = []
        self._boundary: list[tuple[int, np.ndarray]] = []
        self._edges: list[np.ndarray] = []
        self._tags: list[np.ndarray] = []
        self._count = 0

    def add_grid(self, xs, ys, body: int) -> None:
        """Adds body `body` meshed on the grid lines `xs` × `ys` (increasing),
        each cell cut into two counter-clockwise triangles."""
        xs, ys = np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)
        nx, ny = len(xs), len(ys)
        gx, gy = np.meshgrid(xs, ys)
        nodes = np.column_stack([gx.ravel(), gy.ravel()])
        idx = np.arange(nx * ny).reshape(ny, nx) + self._count
        a, b = idx[:-1, :-1].ravel(), idx[:-1, 1:].ravel()
        c, d = idx[1:, 1:].ravel(), idx[1:, :-1].ravel()
        tris = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
        ring = np.concatenate([idx[0, :], idx[1:, -1], idx[-1, -2::-1], idx[-2:0:-1, 0]])
        self._boundary.append((body, np.column_stack([ring, np.roll(ring, -1)])))
        self._nodes.append(nodes)
        self._triangles.append(tris)
        self._bodies.append(np.full(len(tris), body, dtype=np.int32))
        self._count += len(nodes)

    def tag(self, tag: int, body: int, where: Callable[[float, float], bool]) -> int:
        """Tags `tag` on the boundary edges of body `body` whose midpoint
        (x, y) satisfies `where`; the number of edges tagged."""
        nodes = np.concatenate(self._nodes)
        count = 0
        for b, ring in self._boundary:
            if b != body:
                continue
            mid = 0.5 * (nodes[ring[:, 0]] + nodes[ring[:, 1]])
            keep = np.array([bool(where(x, y)) for x, y in mid], dtype=bool)
            self._edges.append(ring[keep])
            self._tags.append(np.full(int(keep.sum()), tag, dtype=np.int32))
            count += int(keep.sum())
        return count

    def nodes_where(self, where: Callable[[float, float], bool]) -> np.ndarray:
        """The nodes (of every body) at which `where(x, y)` holds."""
        nodes = np.concatenate(self._nodes)
        return np.flatnonzero([bool(where(x, y)) for x, y in nodes])

    def arrays(self):
        """(nodes, triangles, bodies, edges, tags) of every body added."""
        empty = np.zeros((0, 2), dtype=np.int64)
        return (
            np.concatenate(self._nodes),
            np.concatenate(self._triangles).astype(np.int64),
            np.concatenate(self._bodies),
            np.concatenate(self._edges).astype(np.int64) if self._edges else empty,
            np.concatenate(self._tags) if self._tags else np.zeros(0, dtype=np.int32),
        )

    def into(self, model) -> None:
        """Sets the model's mesh and tagged edges."""
        nodes, triangles, bodies, edges, tags = self.arrays()
        model.set_mesh(nodes, triangles, bodies)
        if len(edges):
            model.set_boundary_edges(edges, tags)
