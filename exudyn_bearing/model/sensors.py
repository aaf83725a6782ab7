"""The bearing's state sensor: its node states at every sensor write, from which
:meth:`~exudyn_bearing.model.handle.BearingHandle.Results` computes every output afterwards."""
from __future__ import annotations

import numpy as np

from ..races import node_rows

__all__ = ["add_state_sensor"]


def add_state_sensor(mbs, nodes, connector):
    """A user-function sensor storing the bearing's absolute node coordinates and velocities
    at every sensor write (the source of :meth:`BearingHandle.Results`), with the contacts'
    traction where the run computed it there (:mod:`exudyn_bearing.model.recorded_traction`);
    it also reports progress where the runner asked for it."""
    from exudyn.utilities import SensorUserFunction

    ref = connector.reference
    rows = []  # the nodes' rows, an index array (a list index costs 6 us a call), found once

    def record(mbs_, t, sensorNumbers, factors, configuration):
        if not rows:
            rows.append(node_rows(mbs_, nodes))
        if connector.progress is not None:
            connector.progress(t)
        indices = rows[0]
        q = np.asarray(mbs_.systemData.GetODE2Coordinates(configuration=configuration))[indices]
        q_t = np.asarray(mbs_.systemData.GetODE2Coordinates_t(configuration=configuration))[indices]
        row = np.concatenate([q + ref, q_t])
        if connector.recorded is not None:  # the run's traction there, for the outputs
            connector.recorded.keep(t, row, q, q_t)
        return row.tolist()

    return mbs.AddSensor(SensorUserFunction(sensorUserFunction=record, storeInternal=True, writeToFile=False))
