"""The bearing's state sensor: its node states at every sensor write, from which
:meth:`~exudyn_bearing.model.handle.BearingHandle.Results` computes every output afterwards."""
from __future__ import annotations

import numpy as np

from ..races import node_rows

__all__ = ["add_state_sensor"]


def add_state_sensor(mbs, nodes, connector):
    """A user-function sensor storing the bearing's absolute node coordinates and velocities
    at every sensor write (the source of :meth:`BearingHandle.Results`); it also reports
    progress where the runner asked for it."""
    from exudyn.utilities import SensorUserFunction

    ref = connector.reference
    indices = []

    def record(mbs_, t, sensorNumbers, factors, configuration):
        if not indices:
            indices.extend(node_rows(mbs_, nodes))
        if connector.progress is not None:
            connector.progress(t)
        q = mbs_.systemData.GetODE2Coordinates(configuration=configuration)
        q_t = mbs_.systemData.GetODE2Coordinates_t(configuration=configuration)
        return np.concatenate([np.asarray(q)[indices] + ref, np.asarray(q_t)[indices]]).tolist()

    return mbs.AddSensor(SensorUserFunction(sensorUserFunction=record, storeInternal=True, writeToFile=False))
