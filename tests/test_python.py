"""Tests of the Python module `tessera`: every binding, its errors, and two closed forms.

Run by ctest (python/ puts the built module on PYTHONPATH); prints the measured numbers.
"""
import atexit
import inspect
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

# The results folder goes once every model has written into it at exit (atexit runs last
# first: this is registered before the module registers its own).
OUT = tempfile.mkdtemp(prefix="tessera_python_test_")
atexit.register(shutil.rmtree, OUT, True)

import tessera  # noqa: E402

INCLINE = """
set psi = 30
set phi = 20
set c = cos(psi)
set s = sin(psi)
round 0.005
material define rock density=2500
joint define smooth kn=1e10 ks=1e10 friction=phi
joint assign smooth
block (-8*c+s),(-8*s-c) (4*c+s),(4*s-c) 4*c,4*s (-8*c),(-8*s) group=slab material=rock
fix group=slab
block 0,0 c,s (c-s),(s+c) (-s),c group=block material=rock
gravity 0 -9.81
damping none
"""

# A 1 m cube resting on a fixed slab.
STACK3 = """
dimension 3
tolerance 0.01
material define rock density=2600
joint define j kn=1e10 ks=1e10 friction=30
joint assign j
block box -1,-1,-1 2,2,0 group=base material=rock
block box 0,0,0 1,1,1 group=cube material=rock
fix group=base
gravity 0 0 -9.81
"""

# An elastic column 1 m wide and 2 m tall on rollers, under its own weight.
COLUMN = """
round 0.01
material define rock density=2000 E=1e9 nu=0.25
block 0,0 1,0 1,2 0,2 group=column material=rock
zone generate edge=0.25
boundary fix=y y=-0.001,0.001
boundary fix=x x=-0.001,0.001
boundary fix=x x=0.999,1.001
gravity 0 -9.81
"""


def model(script, name):
    m = tessera.Model(out=os.path.join(OUT, name), quiet=True)
    m.command(script)
    return m


class Incline(unittest.TestCase):
    """2D rigid blocks: the block slides down the slab with a = g (sin psi - cos psi tan phi)."""

    @classmethod
    def setUpClass(cls):
        cls.m = model(INCLINE, "incline")
        cls.m.command("history xvel block=2\nhistory time\nhistory interval 100")
        cls.m.cycle(4000)

    def test_sliding_speed_matches_closed_form(self):
        m = self.m
        speed = np.linalg.norm(m.blocks.vel[1])
        psi, phi = math.radians(30), math.radians(20)
        expected = 9.81 * (math.sin(psi) - math.cos(psi) * math.tan(phi)) * m.time
        print(f"incline: speed {speed:.5f} m/s after {m.time:.4f} s, closed form {expected:.5f}")
        self.assertAlmostEqual(speed, expected, delta=0.01 * expected)
        # It slides down the slope: the displacement points along (-cos psi, -sin psi).
        d = m.blocks.disp[1]
        self.assertGreater(np.linalg.norm(d), 0.0)
        self.assertAlmostEqual(d[1] / d[0], math.tan(psi), delta=1e-3)

    def test_block_arrays(self):
        m = self.m
        b = m.blocks
        self.assertEqual(len(b), 2)
        shapes = {"id": (2,), "group": (2,), "pos": (2, 2), "vel": (2, 2), "disp": (2, 2),
                  "rot": (2,), "angvel": (2,), "mass": (2,), "fixity": (2,), "load": (2, 2),
                  "load_moment": (2,)}
        self.assertEqual(sorted(tessera.Blocks.names), sorted(shapes))
        for name, shape in shapes.items():
            self.assertEqual(getattr(b, name).shape, shape, name)
        self.assertEqual(list(b.id), [1, 2])
        self.assertEqual([m.groups[g] for g in b.group], ["slab", "block"])
        self.assertAlmostEqual(b.mass[1], 2500.0, places=6)
        self.assertEqual(b.fixity[0], 7)
        self.assertEqual(b.fixity[1], 0)
        self.assertTrue(np.all(b.vel[0] == 0.0))
        # The block's centroid started at (c - s, s + c)/2 and moved by disp.
        c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
        np.testing.assert_allclose(b.pos[1] - b.disp[1], [(c - s) / 2, (s + c) / 2], atol=1e-9)

    def test_views_are_read_only_and_share_memory(self):
        rot = self.m.blocks.rot
        with self.assertRaises(ValueError):
            rot[0] = 1.0
        self.assertTrue(np.shares_memory(rot, self.m.blocks.rot))
        self.assertFalse(np.shares_memory(self.m.blocks.pos, self.m.blocks.pos))  # 2D: a copy

    def test_contact_arrays(self):
        c = self.m.contacts
        n = len(c)
        self.assertGreaterEqual(n, 2)
        shapes = {"blocks": (n, 2), "normal_force": (n,), "shear_force": (n,), "normal": (n, 2),
                  "force": (n, 2), "gap": (n,), "state": (n,)}
        self.assertEqual(sorted(tessera.Contacts.names), sorted(shapes))
        for name, shape in shapes.items():
            self.assertEqual(getattr(c, name).shape, shape, name)
        self.assertTrue(np.all(np.sort(c.blocks, axis=1) == [1, 2]))
        np.testing.assert_allclose(np.linalg.norm(c.normal, axis=1), 1.0, atol=1e-12)
        # No shear force beyond the Coulomb limit Fn tan(phi) (undamped, the block bounces on
        # its joint as it slides, so the forces themselves vary).
        limit = c.normal_force * math.tan(math.radians(20))
        self.assertTrue(np.all(np.abs(c.shear_force) <= limit * (1 + 1e-9) + 1e-9))
        self.assertGreater(c.normal_force.sum(), 0.0)
        # The force on the first block is Fn along the normal plus Fs across it.
        np.testing.assert_allclose(np.linalg.norm(c.force, axis=1),
                                   np.hypot(c.normal_force, c.shear_force), rtol=1e-9, atol=1e-6)
        with self.assertRaises(ValueError):
            self.m.subcontacts.normal_force

    def test_histories(self):
        h = self.m.histories
        self.assertEqual(h.labels, ["xvel_2", "time"])
        self.assertEqual(len(h), 2)
        self.assertEqual(h.values.shape, (len(h.cycle), 2))
        self.assertTrue(np.all(np.diff(h.cycle) == 100))
        self.assertEqual(h.cycle[-1], 4000)
        np.testing.assert_array_equal(h["xvel_2"], h.values[:, 0])
        self.assertAlmostEqual(h["time"][-1], self.m.time, places=12)
        self.assertIn("time", h)
        self.assertNotIn("ydisp", h)
        with self.assertRaisesRegex(KeyError, "did you mean 'time'"):
            h["tme"]


class Commands(unittest.TestCase):
    """command, cycle, solve, the named writes and the errors that leave the model as it was."""

    def setUp(self):
        self.m = model(INCLINE, "commands")

    def test_error_has_callers_file_and_line(self):
        before = self.m.blocks.pos.copy()
        line = inspect.currentframe().f_lineno + 2
        with self.assertRaises(tessera.ScriptError) as e:
            self.m.command("block 10,10 11,10 11,11\nfrobnicate 3")
        self.assertTrue(str(e.exception).startswith(f"{__file__}:{line + 1}: unknown command"),
                        str(e.exception))
        self.assertEqual((e.exception.file, e.exception.line), (__file__, line + 1))
        self.assertIn("frobnicate", e.exception.message)
        self.assertIsInstance(e.exception, RuntimeError)
        # The first line's block was taken back with the rest.
        self.assertEqual(len(self.m.blocks), 2)
        np.testing.assert_array_equal(self.m.blocks.pos, before)

    def test_cycle_and_solve(self):
        m = self.m
        # The step is known before the first cycle (to size a run by time), and kept by it.
        dt = m.dt
        self.assertGreater(dt, 0.0)
        m.cycle(10)
        self.assertEqual(m.cycles, 10)
        self.assertEqual(m.dt, dt)
        self.assertAlmostEqual(m.time, 10 * m.dt, places=12)
        with self.assertRaises(ValueError):
            m.cycle(-1)
        m.set_joint("smooth", friction=40)  # the block now stands
        m.command("damping local 0.8")
        self.assertTrue(m.solve(ratio=1e-5, cycles=20000))
        self.assertLess(m.ratio, 1e-5)
        # At rest on the slab: sum Fn = m g cos psi and sum Fs = m g sin psi (per metre).
        c, w, psi = m.contacts, 2500 * 9.81, math.radians(30)
        self.assertAlmostEqual(c.normal_force.sum(), w * math.cos(psi), delta=1e-3 * w)
        self.assertAlmostEqual(abs(c.shear_force.sum()), w * math.sin(psi), delta=1e-3 * w)
        self.assertFalse(m.solve(ratio=1e-12, cycles=5))

    def test_failed_run_leaves_model_as_it_was(self):
        m = self.m
        m.cycle(5)
        pos, cycles = m.blocks.pos.copy(), m.cycles
        with self.assertRaisesRegex(tessera.ScriptError, "cycle limit"):
            m.solve(ratio=1e-5, cycles=0)
        self.assertEqual(m.cycles, cycles)
        np.testing.assert_array_equal(m.blocks.pos, pos)

    def test_on_cycle(self):
        m = self.m
        seen = []
        m.on_cycle(lambda model: seen.append(model.cycles), every=25)
        m.cycle(100)
        self.assertEqual(seen, [25, 50, 75, 100])
        m.on_cycle(None)
        m.cycle(50)
        self.assertEqual(len(seen), 4)

    def test_servo_callback_writes_velocity(self):
        m = self.m
        # Hold the block still from cycle 1 on: after each cycle its velocity is set to zero.
        m.on_cycle(lambda model: model.set_velocity([0.0, 0.0], blocks=[2]))
        m.cycle(200)
        self.assertEqual(np.abs(m.blocks.vel[1]).max(), 0.0)
        sliding = 0.5 * 1.81 * m.time ** 2  # how far it would have slid
        self.assertLess(np.linalg.norm(m.blocks.disp[1]), 0.05 * sliding)

    def test_callback_that_raises(self):
        m = self.m
        m.cycle(10)
        pos = m.blocks.pos.copy()

        def bad(model):
            if model.cycles == 30:
                raise ZeroDivisionError("servo gain")

        m.on_cycle(bad)
        with self.assertRaisesRegex(ZeroDivisionError, "servo gain"):
            m.cycle(100)
        self.assertEqual(m.cycles, 10)
        np.testing.assert_array_equal(m.blocks.pos, pos)
        # Cycling again from a callback is refused.
        m.on_cycle(None)
        m.on_cycle(lambda model: model.cycle(1))
        with self.assertRaisesRegex(ValueError, "inside an on_cycle callback"):
            m.cycle(3)
        self.assertEqual(m.cycles, 10)
        with self.assertRaises(ValueError):
            m.on_cycle(print, every=0)

    def test_set_velocity(self):
        m = self.m
        m.set_velocity(np.array([[0.0, 0.0], [0.5, -0.25]]))
        np.testing.assert_array_equal(m.blocks.vel[1], [0.5, -0.25])
        np.testing.assert_array_equal(m.blocks.vel[0], [0.0, 0.0])  # fixed: prescribed zero
        m.set_velocity([1.0, 2.0], blocks=[2], omega=0.25)
        np.testing.assert_array_equal(m.blocks.vel[1], [1.0, 2.0])
        self.assertEqual(m.blocks.angvel[1], 0.25)
        with self.assertRaisesRegex(ValueError, r"shaped \(1, 2\) or \(2,\), not \(3,\)"):
            m.set_velocity([1.0, 2.0, 3.0], blocks=[2])
        with self.assertRaisesRegex(ValueError, "finite"):
            m.set_velocity([math.nan, 0.0], blocks=[2])
        with self.assertRaises(tessera.ScriptError):
            m.set_velocity(np.zeros((2, 2)), blocks=[2, 99])
        np.testing.assert_array_equal(m.blocks.vel[1], [1.0, 2.0])  # the first row was taken back

    def test_set_force(self):
        m = self.m
        m.set_force([10.0, -20.0], blocks=[2], moment=3.0)
        np.testing.assert_array_equal(m.blocks.load[1], [10.0, -20.0])
        self.assertEqual(m.blocks.load_moment[1], 3.0)
        m.set_force(np.zeros((2, 2)), moment=np.array([0.0, 1.5]))
        np.testing.assert_array_equal(m.blocks.load, np.zeros((2, 2)))
        self.assertEqual(m.blocks.load_moment[1], 1.5)
        with self.assertRaisesRegex(ValueError, r"shaped \(1, 2\) or \(2,\), not \(3,\)"):
            m.set_force([1.0, 2.0, 3.0], blocks=[2])
        with self.assertRaisesRegex(ValueError, "set_force\\(moment=\\)"):
            m.set_force([1.0, 2.0], blocks=[2], moment=[1.0, 2.0])
        with self.assertRaisesRegex(tessera.ScriptError, "'load' needs"):
            m.command("load block=2")
        self.assertEqual(m.blocks.load_moment[1], 1.5)  # nothing changed by the failures

    def test_properties_gravity_variables(self):
        m = self.m
        m.set_gravity([0.0, -5.0])
        m.set_variable("k", 2.5)
        self.assertEqual(m.variable("k"), 2.5)
        m.command("set twice = 2 * k")
        self.assertEqual(m.variable("twice"), 5.0)
        with self.assertRaises(KeyError):
            m.variable("nothing")
        m.set_material("rock", density=3000)
        self.assertAlmostEqual(m.blocks.mass[1], 3000.0, places=6)
        with self.assertRaisesRegex(tessera.ScriptError, "friction must be in"):
            m.set_joint("smooth", friction=95)
        with self.assertRaises(TypeError):
            m.set_joint("smooth", friction=[1, 2])
        self.assertEqual(m.dim, 2)
        self.assertEqual(m.groups, ["slab", "block"])
        self.assertTrue(m.out.endswith("commands"))
        self.assertEqual((tessera.BONDED, tessera.SLIPPING, tessera.TOUCHING, tessera.BROKEN),
                         (1, 2, 4, 8))

    def test_histories_without_any_are_two_dimensional(self):
        with tessera.Model(out=os.path.join(OUT, "no_histories"), quiet=True) as m:
            m.command(INCLINE)
            m.cycle(5)
            self.assertEqual(m.histories.values.ndim, 2)
            self.assertEqual(m.histories.values.shape[1], 0)

    def test_finish_writes_results(self):
        out = os.path.join(OUT, "finished")
        with tessera.Model(out=out, quiet=True, threads=1) as m:
            m.command(INCLINE + "history ratio")
            m.cycle(20)
        for f in ("history.csv", "summary.json", "vtk/blocks.pvd"):
            self.assertTrue(os.path.exists(os.path.join(out, f)), f)
        m.finish()

    def test_results_written_at_exit_after_an_error(self):
        out = os.path.join(OUT, "at_exit")
        script = ("import tessera\n"
                  f"m = tessera.Model(out={out!r}, quiet=True)\n"
                  f"m.command({INCLINE!r})\n"
                  "m.cycle(10)\n"
                  "m.command('frobnicate')\n")
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
        self.assertEqual(run.returncode, 1)
        self.assertIn("<string>:5: unknown command 'frobnicate'", run.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary["cycles"], 10)
        # The summary says the program failed, and where.
        self.assertEqual(summary["status"], "error")
        self.assertIn("<string>:5: ScriptError:", summary["error"])
        self.assertIn("unknown command 'frobnicate'", summary["error"])
        # A program that ends well says so, though a model's command failed on the way.
        out = os.path.join(OUT, "at_exit_caught")
        script = ("import tessera\n"
                  f"m = tessera.Model(out={out!r}, quiet=True)\n"
                  f"m.command({INCLINE!r})\n"
                  "try:\n    m.command('frobnicate')\nexcept tessera.ScriptError:\n    pass\n"
                  "m.cycle(10)\n")
        run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary["status"], "completed")
        self.assertNotIn("error", summary)


class Stack3D(unittest.TestCase):
    """3D rigid blocks: the sub-contacts under a cube carry its weight."""

    @classmethod
    def setUpClass(cls):
        cls.m = model(STACK3, "stack3")
        cls.m.solve(ratio=1e-6)

    def test_weight_on_subcontacts(self):
        m, weight = self.m, 2600 * 9.81
        s = m.subcontacts
        print(f"3D cube: sub-contacts carry {s.normal_force.sum():.2f} N of {weight:.2f} N")
        self.assertAlmostEqual(s.normal_force.sum(), weight, delta=1e-4 * weight)
        self.assertAlmostEqual(m.contacts.normal_force.sum(), weight, delta=1e-4 * weight)
        self.assertAlmostEqual(s.area.sum(), 1.0, places=9)
        n = len(s)
        self.assertEqual(n, 4)
        shapes = {"contact": (n,), "point": (n, 3), "area": (n,), "normal_force": (n,),
                  "shear_force": (n, 3), "gap": (n,), "state": (n,)}
        self.assertEqual(sorted(tessera.SubContacts.names), sorted(shapes))
        for name, shape in shapes.items():
            self.assertEqual(getattr(s, name).shape, shape, name)
        np.testing.assert_allclose(np.sort(s.point[:, 0]), [0, 0, 1, 1], atol=1e-6)
        self.assertTrue(np.all(s.contact == 0))

    def test_pressed_cube_joint_carries_weight_and_load(self):
        m = model(STACK3, "stack3_load")
        m.set_force([[0.0, 0.0, 0.0], [0.0, 0.0, -1e4]], moment=np.zeros((2, 3)))
        np.testing.assert_array_equal(m.blocks.load[1], [0.0, 0.0, -1e4])
        m.solve(ratio=1e-6)
        carried, expected = m.subcontacts.normal_force.sum(), 2600 * 9.81 + 1e4
        print(f"3D cube pressed by 10 kN: sub-contacts carry {carried:.2f} N of {expected:.2f} N")
        self.assertAlmostEqual(carried, expected, delta=1e-4 * expected)

    def test_set_force_on_a_joined_body(self):
        m = model(STACK3 + "block box 1,0,0 2,1,1 group=cube material=rock\njoin group=cube\n",
                  "joined_load")
        load = np.zeros((3, 3))
        load[1] = [0.0, 0.0, -1e4]  # the body's first piece; its other piece's row is not used
        m.set_force(load)
        np.testing.assert_array_equal(m.blocks.load, load)
        m.set_force(2 * m.blocks.load)
        self.assertEqual(m.blocks.load[1, 2], -2e4)

    def test_set_velocity_on_a_joined_body_with_spin(self):
        m = model(STACK3 + "block box 1,0,0 2,1,1 group=cube material=rock\njoin group=cube\n",
                  "joined_spin")
        v, w = np.zeros((3, 3)), np.zeros((3, 3))
        v[1], w[1] = [0.1, 0.0, 0.0], [0.0, 0.0, 0.5]  # the body's first piece
        v[2] = [9.0, 9.0, 9.0]  # its other piece's row is not used
        m.set_velocity(v, omega=w)
        np.testing.assert_array_equal(m.blocks.vel[1], [0.1, 0.0, 0.0])
        np.testing.assert_allclose(m.blocks.angvel[1], [0.0, 0.0, 0.5], atol=1e-12)
        with self.assertRaisesRegex(ValueError, r"omega=\) takes an array shaped \(1, 3\)"):
            m.set_velocity([0.0, 0.0, 0.0], blocks=[2], omega=[1.0, 2.0])

    def test_arrays_3d(self):
        m = self.m
        b, c = m.blocks, m.contacts
        self.assertEqual(m.dim, 3)
        for name, shape in {"pos": (2, 3), "vel": (2, 3), "disp": (2, 3), "rot": (2,),
                            "angvel": (2, 3), "mass": (2,), "fixity": (2,), "load": (2, 3),
                            "load_moment": (2, 3)}.items():
            self.assertEqual(getattr(b, name).shape, shape, name)
        self.assertTrue(np.shares_memory(b.pos, m.blocks.pos))  # 3D rigid blocks: a view
        np.testing.assert_allclose(b.pos[1], [0.5, 0.5, 0.5], atol=1e-4)
        self.assertAlmostEqual(b.mass[1], 2600.0, places=6)
        self.assertEqual(c.blocks.tolist(), [[1, 2]])
        np.testing.assert_allclose(np.abs(c.normal[0]), [0, 0, 1], atol=1e-9)
        self.assertEqual(c.shear_force.shape, (1, 3))
        self.assertEqual(c.force.shape, (1, 3))
        self.assertTrue(c.state[0] & tessera.TOUCHING)
        m.set_velocity([0.0, 0.0, 0.1], blocks=[2])
        self.assertEqual(m.blocks.vel[1, 2], 0.1)


class Column(unittest.TestCase):
    """Zones and nodes: an elastic column under its own weight, syy = -rho g (H - y)."""

    @classmethod
    def setUpClass(cls):
        cls.m = model(COLUMN, "column")
        cls.m.solve(ratio=1e-6)

    def test_stress_matches_weight(self):
        z = self.m.zones
        depth = 2.0 - z.centroid[:, 1]
        expected = -2000 * 9.81 * depth
        err = np.abs(z.stress[:, 1] - expected).max() / (2000 * 9.81 * 2.0)
        print(f"column: {len(z)} zones, largest syy error {100 * err:.2f}% of the base stress")
        self.assertLess(err, 0.05)

    def test_zone_and_node_arrays(self):
        m = self.m
        z, n = m.zones, m.nodes
        nz, nn = len(z), len(n)
        self.assertGreater(nz, 10)
        for name, shape in {"stress": (nz, 6), "nodes": (nz, 3), "state": (nz,),
                            "material": (nz,), "centroid": (nz, 2)}.items():
            self.assertEqual(getattr(z, name).shape, shape, name)
        for name, shape in {"pos": (nn, 2), "disp": (nn, 2), "vel": (nn, 2), "applied": (nn, 2),
                            "mass": (nn,)}.items():
            self.assertEqual(getattr(n, name).shape, shape, name)
        self.assertEqual(sorted(tessera.Zones.names), sorted(["stress", "nodes", "state",
                                                              "material", "centroid"]))
        self.assertEqual(sorted(tessera.Nodes.names), sorted(["pos", "disp", "vel", "applied",
                                                              "mass"]))
        self.assertTrue(np.all(z.material == 1))
        self.assertLess(z.nodes.max(), nn)
        self.assertAlmostEqual(n.mass.sum(), 2000 * 2.0, places=6)
        base = n.pos[:, 1] - n.disp[:, 1] < 1e-9  # the nodes on the rollers at y = 0
        self.assertGreater(base.sum(), 2)
        self.assertEqual(np.abs(n.disp[base, 1]).max(), 0.0)
        self.assertLess(n.disp[:, 1].min(), 0.0)  # it settles

    def test_node_force(self):
        m = self.m
        top = np.flatnonzero(m.nodes.pos[:, 1] > 1.999)
        m.set_node_force([0.0, -1000.0], nodes=top.tolist())
        np.testing.assert_array_equal(m.nodes.applied[top], [[0.0, -1000.0]] * len(top))
        with self.assertRaises(IndexError):
            m.set_node_force([0.0, 0.0], nodes=[len(m.nodes)])
        with self.assertRaises(ValueError):
            m.set_node_force(np.zeros((2, 3)), nodes=[0, 1])
        m.set_node_force([0.0, 0.0])
        self.assertEqual(np.abs(m.nodes.applied).max(), 0.0)


# One free 1 m square block, no contacts, a fixed time step of 1 ms.
LONE = """
round 0.01
material define rock density=1000
block 0,0 1,0 1,1 0,1 material=rock
damping none
timestep fixed 1e-3
"""


class Tables(unittest.TestCase):
    """Tables as time histories of velocities, gravity and boundary loads; contact histories."""

    def test_velocity_follows_a_ramp(self):
        m = model(LONE, "ramp_velocity")
        m.set_table("ramp", [0.0, 1.0], [0.0, 1.0])
        m.command("fix block=1\nvelocity block=1 vx=2 table=ramp")
        m.cycle(1000)
        # v = 2 t: x = t^2 at t = 1 s (to the step's first order).
        print(f"ramp velocity: x = {m.blocks.disp[0, 0]:.5f} m at {m.time:.4f} s, closed form 1")
        self.assertAlmostEqual(m.blocks.disp[0, 0], 1.0, delta=0.005)
        self.assertAlmostEqual(m.blocks.vel[0, 0], 2.0, delta=0.005)
        m.command("table stop")
        m.cycle(100)  # held at its last velocity
        self.assertAlmostEqual(m.blocks.vel[0, 0], 2.0, delta=0.005)

    def test_gravity_from_a_csv_file(self):
        path = os.path.join(OUT, "g.csv")
        with open(path, "w") as f:
            f.write("time,factor\n0,0\n0.5,1 # full gravity from half a second\n")
        m = model(LONE, "csv_gravity")
        m.command(f"table g {path}\ngravity 0 -10 table=g")
        m.cycle(1000)
        # a = -20 t up to 0.5 s, then -10: v(1) = -2.5 - 5 = -7.5 m/s.
        print(f"gravity table: vy = {m.blocks.vel[0, 1]:.4f} m/s at 1 s, closed form -7.5")
        self.assertAlmostEqual(m.blocks.vel[0, 1], -7.5, delta=0.02)

    def test_boundary_stress_and_velocity_follow_tables(self):
        m = model(COLUMN, "column_tables")
        m.command("timestep fixed 1e-5\ntable half 0,0 1e-3,0.5 2e-3,1")
        m.command("boundary stress=0,-1e6,0 y=1.999,2.001 table=half")
        top = m.nodes.pos[:, 1] > 1.999
        m.cycle(100)  # t = 1 ms: half the stress, 0.5 MN/m on the 1 m top
        self.assertAlmostEqual(m.nodes.applied[top, 1].sum(), -0.5e6, delta=1.0)
        m.cycle(200)  # beyond the table's end: the whole stress, added once
        self.assertAlmostEqual(m.nodes.applied[top, 1].sum(), -1e6, delta=1.0)
        m.command("boundary velocity=0,-1 y=1.999,2.001 table=half")
        m.cycle(1)
        np.testing.assert_allclose(m.nodes.vel[top, 1], -1.0, atol=1e-12)

    def test_table_errors(self):
        m = model(LONE, "table_errors")
        m.set_table("ramp", [0.0, 1.0], [0.0, 1.0])
        with self.assertRaisesRegex(tessera.ScriptError, "table= goes with"):
            m.command("fix block=1 table=ramp")
        with self.assertRaisesRegex(tessera.ScriptError, "no table 'rmp' \\(did you mean 'ramp'"):
            m.command("velocity block=1 vx=1 table=rmp")
        with self.assertRaisesRegex(ValueError, "times must increase"):
            m.set_table("bad", [0.0, 0.0], [1.0, 2.0])
        with self.assertRaisesRegex(tessera.ScriptError, "is not a pair"):
            m.command("table t 0,1 2")
        path = os.path.join(OUT, "bad.csv")
        with open(path, "w") as f:
            f.write("0,1\n1,x\n")
        with self.assertRaisesRegex(tessera.ScriptError, "bad.csv:2: write time,value"):
            m.command(f"table t {path}")
        m.cycle(10)
        self.assertEqual(m.blocks.vel[0, 0], 0.0)  # nothing follows a table

    def test_contact_force_histories(self):
        m = model(STACK3, "contact_histories3")
        m.command("history normal_force contact=1,2\nhistory shear_force contact=2,1 label=fs")
        m.solve(ratio=1e-6)
        h = m.histories
        self.assertEqual(h.labels, ["normal_force_1_2", "fs"])
        print(f"3D normal_force history: {h['normal_force_1_2'][-1]:.2f} N of 25506.00 N")
        self.assertAlmostEqual(h["normal_force_1_2"][-1], 2600 * 9.81, delta=1.0)
        self.assertLess(h["fs"][-1], 1e-3)
        with self.assertRaisesRegex(tessera.ScriptError, "needs contact=A,B"):
            m.command("history normal_force")
        with self.assertRaisesRegex(tessera.ScriptError, "there is no block 7"):
            m.command("history normal_force contact=1,7")
        m2 = model(INCLINE, "contact_histories2")
        m2.command("joint define smooth friction=40\ndamping local 0.8\n"
                   "history normal_force contact=1,2\nhistory shear_force contact=1,2")
        m2.solve(ratio=1e-6)
        w, psi = 2500 * 9.81, math.radians(30)
        self.assertAlmostEqual(m2.histories["normal_force_1_2"][-1], w * math.cos(psi),
                               delta=1e-3 * w)
        self.assertAlmostEqual(m2.histories["shear_force_1_2"][-1], w * math.sin(psi),
                               delta=1e-3 * w)


if __name__ == "__main__":
    unittest.main(verbosity=2)
