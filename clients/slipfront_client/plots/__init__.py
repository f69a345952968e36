"""The paper's figures from slipfront runs, one small module per figure:

- `slip_map`     (a) |V| in the x1–t plane with the slip front (paper Fig. 2a)
- `velocity`     (b) slip velocity against time at given x1 (Fig. 2b, 3a, 4a)
- `speed`        (c) rupture speed against x1 with c_s and c_p (Fig. 2c, 3b, 4b)
- `convergence`  (d) convergence map in the L–n_d plane (Fig. 3c, 4c)
- `filter_response` (e) A/A0 of the friction filter against frequency (Fig. 5c, eq. 6)
- `mesh_convergence`   |V| at x1 = 6 and 10 m and V_r, every n_d of one L (Fig. 3a, 3b)
- `length_convergence` the same for the mesh-converged run of each L, L_c thick (Fig. 4a, 4b)
- `strength_spectrum`  tau_s at x1 = 6 m, its power spectrum, A/A0 with the meshes (Fig. 5)
- `critical_frequency` L_c against the event's frequency from runs (Fig. 6)
- `cost`         (f) wall time against error, one curve per L
- `length_fit`   the length fit of Sec. 6: measured and fitted stress, spectrum with f_m

Each `plot_*` function returns `(figure, data)`: `data` holds the arrays drawn, so tests
(and users) can check a figure against its sources.
"""
