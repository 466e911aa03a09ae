"""The race problems in Exudyn's ANCFCable2D (engineering strain, curvature
|r_x x r_xx| / |r_x|^2, 5 axial / 3 bending Gauss points, generalized-alpha:
its defaults, as in data/reference/README.md)."""
import time
import numpy as np
import exudyn as exu
from exudyn.itemInterface import ObjectANCFCable2D, SensorNode
from exudyn.beams import GenerateStraightLineANCFCable2D

GUTTA = dict(E=0.91e6, rho=1202.0, A=1.075e-5, I=9.15e-12)
PVC = dict(E=3.4e9, rho=1380.0, A=3.0e-6, I=1.25e-13)


def _cable(m):
    return ObjectANCFCable2D(
        physicsMassPerLength=m["rho"] * m["A"],
        physicsBendingStiffness=m["E"] * m["I"],
        physicsAxialStiffness=m["E"] * m["A"],
    )


def _solve(mbs, sensor, end_time, dt, write_period):
    s = exu.SimulationSettings()
    s.timeIntegration.endTime = end_time
    s.timeIntegration.numberOfSteps = int(round(end_time / dt))
    s.timeIntegration.verboseMode = 0
    s.timeIntegration.generalizedAlpha.spectralRadius = 0.9
    s.solutionSettings.writeSolutionToFile = False
    s.solutionSettings.sensorsWritePeriod = write_period
    s.displayComputationTime = False
    s.displayStatistics = False
    t0 = time.perf_counter()
    exu.SolveDynamic(mbs, s)
    wall = time.perf_counter() - t0
    return wall, mbs.GetSensorStoredData(sensor)


def pendulum(elements, dt):
    """The paper's pendulum without drag: tip positions (t, x, y) every
    10 ms and the wall time of the solve."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    nodes = GenerateStraightLineANCFCable2D(
        mbs, [0, 0, 0], [0.5, 0, 0], elements, _cable(GUTTA),
        massProportionalLoad=[0, -9.81, 0], fixedConstraintsNode0=[1, 1, 0, 0],
    )[0]
    sensor = mbs.AddSensor(SensorNode(nodeNumber=nodes[-1], storeInternal=True,
                                      outputVariableType=exu.OutputVariableType.Position))
    mbs.Assemble()
    wall, data = _solve(mbs, sensor, 0.8, dt, 0.01)
    return wall, data[:, :3]


def impact(elements, dt):
    """The paper's transverse impact (PVC, 10 m/s at both ends), 0.3 s:
    tip (end B) positions every 10 ms and the wall time."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    nodes = GenerateStraightLineANCFCable2D(mbs, [-2, 0, 0], [2, 0, 0], elements, _cable(PVC))[0]
    mbs.SetNodeParameter(nodes[0], "initialVelocities", [0, 10.0, 0, 0])
    mbs.SetNodeParameter(nodes[-1], "initialVelocities", [0, -10.0, 0, 0])
    sensor = mbs.AddSensor(SensorNode(nodeNumber=nodes[-1], storeInternal=True,
                                      outputVariableType=exu.OutputVariableType.Position))
    mbs.Assemble()
    wall, data = _solve(mbs, sensor, 0.3, dt, 0.01)
    return wall, data[:, :3]


if __name__ == "__main__":
    w, d = pendulum(64, 1e-4)
    print("pendulum 64 el dt 1e-4: %.2f s, tip at %.2f s: %s" % (w, d[-1, 0], d[-1, 1:]))
    w, d = impact(8, 1e-4)
    print("impact 8 el dt 1e-4: %.2f s, tip at %.2f s: %s" % (w, d[-1, 0], d[-1, 1:]))
