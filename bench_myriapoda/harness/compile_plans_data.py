"""Compile plans recorded by ``python -m bench_myriapoda.harness.cold_compile --record``: generated, do not edit.

recorded on the merged tree (kernels30, legged30c, world30c, gait30, shape27c), each group in a fresh process on an empty numba cache, 2-core machine
"""
NUMBA_VERSION = '0.68.1'
PLANS = {'fem-legged-dry': {'args': 'eNrtGl1v21Q0TZNsAzTQxlhJtyoyEgqTSbTWQssbWQUSZNkDGlLRVFWO4/Z6S+wqcQrWNAkhNQHJb3VBDCh9RPDER8WXpv2AIfE1XvgBiBckxAPP3G879nX6mSJtqdXWvveec889X/eec8+bqfX6swn8M+/l8+6TZqdZUwua1dILtrOstwtqrW23VM323JMLqGWhpWuWCds6mm21vDXPPaJZy05LX/Lc49HOKEJz2cEvnpsut1qqg0YdrXWMhm2YsDFj1a7pcLo173LPu+nl3XQdDffAOMi4ExFsbU1tqC2E7MWGpSIw8AgFTJlqU4fkLaKO5xQ0i2G/btRt4FWed9MLmlXXvcqZTs97xYOD60bTqyTdTEN1rA5c7tisx1CcUhGheYpIzk3X5dzsMx7DUV1LYiSIRHCMzQ8exd+PuUdeMm19SW8FaAOn3LRhIqLAaUhLpm0smXrdextMVLIE1WQlCc6As2DKPUkmx8P51CBX9WImzULYcQobJnyGQ68PgB6LgT7Pod8l0DYEKYISetCrQl6BZEfxygG8/Svysb5HaSqDUg8CyRBVFj12/wd5QyMGNaFXWfABH5k1+E20g3RlxU8YTR/MAHSki75mY+kL9EiQlRJ74OrkVTxC8kf5TCfNJQLGMQSIRqzr4t4iRqsABTaiL6mH/ktd0ZIpT6UenwLCCbUlFaMtCpfrLV9bCIkSI1HGVj0ZsWroRGzVMHVs2Fc6yw09aNhp4j8QYWVMEuAkXc/DJsa6GHO8aFkNXTX7zTFVg60etL8TzP6Ytp4g60L9QWX9gCqrwx8iNQcTUBI+Ch5R4uPJuwI0ZjZuWrM6pu1VZEruonvsVdOwzCvIBQYIhut0sFwQcBkKa8pdxQOvRqmVhWYsC32aLHQYslC0ssCM5xFrPqSsmZq7N55IYPHlBWPlnJiEg2zu48Mhtm1H5cxeid8TB88/yM0z+5BADO5hasaeCdhuZcpBMJNQhx3gR9TK6U4EblQy1Gnd9N0U6CIn3UO+IJ1KJIiLGnmEkUcYeYT7yyMMPGREjwgb/IhwKdV/RIiZL6TlIxcyciEjF3KfuZCDkBQ+mnwcSG4sug9dVpt6PS6KDAWQ6yxQLsPHwfEcDZl5bPZwMCUVOOys5+ngMijaPHfU3GlYtoMArN9OBXmheT8n9SPlwYb7r9C9Tos8wI4ci9BbCBt3oaoH6O9mmCJsVn8KKEJAxiKZo1i8GEoZ3MLfTwfSBJmOn7YD594BE5Un+vKHYzx/CM5C1j9OSOuEUl2b1Z8pYVs8WVHGT4n+LdJvieYJSB7o/cokpSmkdSWMoAi2bCTwtw4wE7CtysmiJc6jNf7CNHDutWTMHr8fdyVU2Y5QDzuHfkTYuY0MJm04CIZD6/SwtqnpbWLRzeqvQju/TnKs5Dc+RIX9XZRAk4JmE2YgXjo+un7Kjq6uNfDcSpm1p974re0zFnX3kDsYj7oDcBfcwb0bc38kRRH3IRAqj4x9ZOxDMXbxDoa3m3t8u/mTbzcjPRzp4XD0MHfYLjV2T9is/kY0v4t2hKSbWTT0Rh3dpNcalnYd3aBpQDVM2O8eN8y2rZqavqA11DbseqqmmxpYaDotQ1226mqhZtUNvV1Y1JsF1gjBLiJMswjLJX2pjaKojbm/xxOJ/vb8gxloMF0YOZuRs7m/nQ32Nr/Hn7VFF+7B6DkFibmAYuej4ByqdTkdrnU5waVwIVjq8jmdUqH3/cE5VqLgRDA++BccHN2WKzgQOBYNBPLgH3xHr8FZ/sJX6oJAenoXgfRuL8/l6OpxxPEljzh+2Fmm/MJ+HGzfOveX91S2SdDkql8FS0MUXNdSxneGJGAjoRkuoGGFKKz4JaJ+vLgCyzctki8tmcCyvTq8cgkstE+40DpCoQ05g4y5+3WcqQbKT2LDYswsdHPrvnAQrMJM+YYzpRtkyv+W5sZc+lbMJeQJuog5SQFzSN+UOy3MGQwyfMyH7zgfZnajHIpP9PcUwwqpAStF6shQVZDgsywsigtVj8nU0pByrKCn52FAp0ft1CEpFTYxKepChrWrqj3foCN1dn4VWpaAwYEyA5cC3dIqJ6lE6sria+xIOtXBQ8niZOxfZOZfJH80qbmT/Jo+hkCidV4yMZ485QSpzSMXDkehUoSvG3Cx3I3KOCqUY91MsLk3cjNYqLeJUK+9PJZIhBjof9K58CD8B3U4fs2gHa4VZP0yqRJEgvQLDB0sOalPAUB2lYtAwu42sHpEwgpiIQEh1yRselwAhzrugLuI9zatO2RJ7i2U8ParD/N+bjuPqeIf2UFFmMLGLZJLJzMSHelPqUtkDfw1wNowLkEXVmC4NTEFVshpwuaFlSU2d5HVwdpUgWSmbnrhPzNvBq8=',
                    'case': 'centipede/fem/walk',
                    'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.774,
                                0.774,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.213,
                                0.213,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                0.401,
                                0.401,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                'array(int64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.356,
                                0.356,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                0,
                                None,
                                14.071,
                                0.797,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_phi',
                                'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                1,
                                4,
                                7.566,
                                0.447,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                'float64)',
                                2,
                                5,
                                0.351,
                                0.35,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                2,
                                5,
                                0.445,
                                0.171,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                'float64, float64)',
                                3,
                                7,
                                0.274,
                                0.274,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                'float64, float64, float64)',
                                2,
                                5,
                                6.323,
                                0.436,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                9,
                                5.888,
                                1.172,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, int64)',
                                4,
                                10,
                                4.716,
                                1.608,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._candidate',
                                'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                1.07,
                                0.613,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                6,
                                12,
                                0.457,
                                0.457,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._descend',
                                'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.783,
                                0.783,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.787,
                                0.787,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                'int64, int64)',
                                5,
                                11,
                                0.467,
                                0.467,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                1,
                                4,
                                5.708,
                                4.92,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                2,
                                17,
                                0.4,
                                0.4,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                2,
                                17,
                                0.388,
                                0.388,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                0,
                                None,
                                1.265,
                                0.262,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.side_sign',
                                'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                1,
                                20,
                                0.091,
                                0.091,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, float64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                1,
                                20,
                                0.912,
                                0.286,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_root',
                                'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), array(float64, 1d, C))',
                                2,
                                22,
                                0.48,
                                0.253,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.matvec',
                                'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                23,
                                0.227,
                                0.227,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                'float64, float64)',
                                2,
                                22,
                                0.146,
                                0.146,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, 1d, '
                                'C))',
                                0,
                                None,
                                0.212,
                                0.212,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_poses',
                                'bench_myriapoda.bodies.fem.myriapod.block_poses(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C))',
                                0,
                                None,
                                3.114,
                                0.51,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_centroids',
                                'bench_myriapoda.bodies.fem.myriapod.block_centroids(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C))',
                                1,
                                27,
                                0.228,
                                0.228,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                1,
                                27,
                                2.376,
                                0.332,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                2,
                                29,
                                2.044,
                                2.044,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                'float64, array(float64, 2d, C))',
                                0,
                                None,
                                0.154,
                                0.154,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C), array(float64, 4d, C))',
                                0,
                                None,
                                0.682,
                                0.486,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, 2d, '
                                'C), float64, float64, array(float64, 2d, C))',
                                1,
                                32,
                                0.196,
                                0.196,
                                False,
                                True),
                               ('bench_myriapoda.fused.legged_walk.legged_chunk',
                                'bench_myriapoda.fused.legged_walk.legged_chunk(float64, float64, int64, '
                                'Tuple(array(float64, 1d, C), array(int64, 1d, C), Tuple(array(int64, 1d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                'C), array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                '3d, C), array(float64, 2d, C), array(bool, 1d, C), array(int64, 1d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                'C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 1d, C), array(bool, 1d, C), array(float64, 3d, C), array(float64, '
                                '4d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)), '
                                'BlockChainLegs(Tuple(array(float64, 2d, C), array(int64, 2d, C), array(float64, 3d, '
                                'C), array(int64, 1d, C), array(int64, 1d, C), array(bool, 1d, C), array(float64, '
                                '2d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C)), Tuple(Tuple(array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 1d, C), array(int64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, '
                                'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                'C), array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                '1d, C), array(int64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 2d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C)), '
                                'Tuple(array(float64, 1d, C), int64, array(float64, 1d, C), int64, array(float64, '
                                '1d, C), array(float64, 1d, C)), array(float64, 1d, C))), Tuple(array(float64, 1d, '
                                'C), array(int8, 2d, C), array(float64, 3d, C), array(int64, 1d, C), array(bool, 2d, '
                                'C), array(float64, 3d, C), array(float64, 3d, C), array(float64, 4d, C), '
                                'array(float64, 3d, C)))',
                                0,
                                None,
                                74.85,
                                13.321,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled.controller_step',
                                'bench_myriapoda.controllers.myriapod.compiled.controller_step(array(float64, 2d, '
                                'C), array(float64, 3d, C), float64, array(float64, 1d, C), array(int64, 1d, C), '
                                'Tuple(array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, '
                                'C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(bool, '
                                '1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '3d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), array(float64, '
                                '3d, C), array(float64, 4d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                'array(float64, 2d, C)), array(float64, 1d, C), array(float64, 1d, C), '
                                'array(float64, 1d, C))',
                                1,
                                34,
                                40.588,
                                4.704,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                'int64)',
                                2,
                                35,
                                1.872,
                                1.308,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                'int64, int64)',
                                3,
                                36,
                                0.562,
                                0.562,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_step',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_step(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, array(float64, 1d, C), array(float64, 1d, '
                                'C), Tuple(array(float64, 3d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                'array(float64, 1d, C), array(bool, 1d, C)), Tuple(array(bool, 1d, C), array(bool, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'array(bool, 1d, C)), Tuple(array(float64, 3d, C), array(float64, 4d, C)), bool)',
                                2,
                                35,
                                5.737,
                                3.537,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                '1d, C), array(float64, 1d, C), float64, float64)',
                                3,
                                38,
                                0.214,
                                0.214,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                3,
                                38,
                                1.038,
                                0.193,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                'float64, float64, float64, float64, array(int64, 1d, C))',
                                4,
                                40,
                                0.845,
                                0.846,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                'array(int64, 1d, C), int64, float64, float64, float64)',
                                3,
                                38,
                                0.204,
                                0.204,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                38,
                                0.514,
                                0.514,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                '2d, C), float64, float64, float64)',
                                3,
                                38,
                                0.23,
                                0.23,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.tips_touching',
                                'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                2,
                                35,
                                0.774,
                                0.774,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                2,
                                35,
                                0.12,
                                0.12,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, 1d, '
                                'C), int64, array(bool, 1d, C))',
                                2,
                                35,
                                0.26,
                                0.26,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                2,
                                35,
                                8.824,
                                1.914,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                'array(float64, 1d, C), float64, float64, float64)',
                                3,
                                48,
                                5.77,
                                4.966,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_normal',
                                'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                4,
                                49,
                                0.804,
                                0.352,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                'float64)',
                                5,
                                50,
                                0.28,
                                0.28,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                5,
                                50,
                                0.171,
                                0.171,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                'float64, float64, float64)',
                                3,
                                48,
                                0.53,
                                0.218,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                'float64, float64)',
                                4,
                                53,
                                0.192,
                                0.091,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                'float64)',
                                5,
                                54,
                                0.101,
                                0.101,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                '2d, C), int64, float64)',
                                4,
                                53,
                                0.12,
                                0.12,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64)',
                                3,
                                48,
                                0.151,
                                0.151,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, C))',
                                3,
                                48,
                                0.458,
                                0.458,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                'array(float64, 2d, C))',
                                2,
                                35,
                                4.973,
                                1.122,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                3,
                                59,
                                3.71,
                                3.71,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                59,
                                0.141,
                                0.141,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 1d, C), float64, array(bool, 1d, C))',
                                2,
                                35,
                                1.463,
                                0.796,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                3,
                                62,
                                0.081,
                                0.081,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                3,
                                62,
                                0.104,
                                0.104,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                62,
                                0.162,
                                0.162,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                3,
                                62,
                                0.093,
                                0.093,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, C), '
                                'int64, float64, float64, float64, float64)',
                                3,
                                62,
                                0.226,
                                0.226,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'array(bool, 1d, C))',
                                2,
                                35,
                                4.805,
                                1.119,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'float64, UniTuple(float64 x 3), UniTuple(float64 x 3), float64)',
                                3,
                                68,
                                3.053,
                                2.326,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                4,
                                69,
                                0.727,
                                0.727,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, '
                                '1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3))',
                                3,
                                68,
                                0.632,
                                0.632,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C))',
                                2,
                                35,
                                0.511,
                                0.315,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_tip',
                                'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), float64, float64, float64, float64)',
                                3,
                                72,
                                0.196,
                                0.196,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                2,
                                35,
                                1.214,
                                1.214,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                2,
                                35,
                                3.691,
                                3.158,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                75,
                                0.145,
                                0.145,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs._wrap',
                                'bench_myriapoda.kinematics.legs._wrap(float64)',
                                3,
                                75,
                                0.066,
                                0.066,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs._ik_solve',
                                'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, array(float64, '
                                '2d, C), float64, array(float64, 1d, C), float64)',
                                3,
                                75,
                                0.322,
                                0.322,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'bool, array(bool, 1d, C), array(float64, 1d, C))',
                                2,
                                35,
                                1.641,
                                1.641,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.carry_blocks',
                                'bench_myriapoda.bodies.fem.myriapod.carry_blocks(array(float64, 2d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '3d, C), array(float64, 2d, C), array(bool, 1d, C))',
                                2,
                                34,
                                0.46,
                                0.46,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.advance_chain',
                                'bench_myriapoda.bodies.fem.myriapod.advance_chain(Tuple(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), array(uint64, '
                                '1d, C), array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(int64, 2d, C), array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(bool, 1d, '
                                'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C)), Tuple(array(float64, 1d, C), int64, array(float64, 1d, C), '
                                'int64, array(float64, 1d, C), array(float64, 1d, C)), array(float64, 1d, C), int64)',
                                2,
                                34,
                                18.798,
                                6.75,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                'array(float64, 2d, C))',
                                3,
                                81,
                                8.525,
                                0.512,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                0.267,
                                0.267,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                4.208,
                                4.208,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                3.079,
                                1.606,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                5,
                                85,
                                1.473,
                                1.271,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                6,
                                86,
                                0.203,
                                0.203,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), array(uint64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                0.458,
                                0.458,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                3,
                                81,
                                2.18,
                                0.596,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                4,
                                89,
                                1.584,
                                1.584,
                                False,
                                True),
                               ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64, float64)',
                                3,
                                81,
                                0.59,
                                0.59,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                3,
                                81,
                                0.752,
                                0.752,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled.finish_chunk',
                                'bench_myriapoda.controllers.myriapod.compiled.finish_chunk(array(float64, 1d, C), '
                                'array(int64, 1d, C), Tuple(array(int64, 1d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(bool, '
                                '1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                'C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 2d, C), array(bool, 1d, C), array(int64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), array(float64, '
                                '2d, C), array(float64, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'array(bool, 1d, C), array(float64, 3d, C), array(float64, 4d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C)))',
                                1,
                                34,
                                1.684,
                                1.015,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, C), '
                                'float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                'array(float64, 4d, C))',
                                2,
                                93,
                                0.668,
                                0.668,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                0.538,
                                0.538,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.533,
                                0.533,
                                False,
                                True),
                               ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), int64, '
                                'int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                0,
                                None,
                                0.764,
                                0.764,
                                False,
                                True)]},
 'fem-legless-dry': {'args': 'eNqNVM2L00AUt902qyAqu66ucVdKDlIltKhB6M26IEhZD96lTJKxE22Tkk6QHgRPVmEusrOIJ/1Tna9MZtIP3YHs+5j3e783771+aV2unCvi7x3tdsm9tJiFoBdlOezh5RwueiBc4BxEmJLDMbeMcxhlKbMVEc5yekHJfpTNlzmcUHJj3bkOmM6XQqCkPcxzsOS3roZFMsVJyoxOFn6ALN0FfbOin2mXtGN+naI95JDjNbRFBKYg52CvphngYei6CmylYAYZvffc8TzgWRL8KYkxoqMXpD2OshjS0Umxom8puxwnMzpqEmcKllnBym2c0RLiCHCiXQXkd57GfufsES0xzmlTgHCK6FqZH90U+i2y/zrFcAJzgxs6Iu0k5aTQXcbFWSSTFMb0GzoeuRLq/qiJTtApekAOZXJxXadGnfPfW5K6LHZPxdaJP9PRlzuiG1uin+joHzIas5A+GvDDxUCKyMPruL6Ba1dUof5SnIZosGJBPoNy+cG2IiV+Y5eJi/4GhR2/NFQm5ZAud/Opw1gxO+CkS4nuVn6Gx2PCQEEEpsGTiseUvn7uofgG7P9QyPWvLzINxDcQ0fxYDTKXDD00ptQpqjFFj7+z+bxj7UtD7ws6LbfltmxvYfdXL8sf1eVIU/Hs8ZH18JLV/rzMsikEqb0/rZBZKSN0IOGC8nH6GjXiORgzYVupl/PkPd9U3F0t/39jJGuSNGQFdk+EyxA9oWhG1gz4W0fZ/8fcG0B1hhtc1US55fsF1UqXqh48RVgOknhb76uuRMLXV/+jsfoHcjZ478zN/1n+nsDeX7riKJw=',
                     'case': 'worm/fem/flat',
                     'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                 'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.753,
                                 0.753,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                 'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.271,
                                 0.271,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                 'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 0.554,
                                 0.554,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.408,
                                 0.408,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                 'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                 'C), float64, float64, float64)',
                                 0,
                                 None,
                                 19.749,
                                 0.911,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_phi',
                                 'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 1,
                                 4,
                                 10.495,
                                 0.863,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                 'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                 'float64)',
                                 2,
                                 5,
                                 0.302,
                                 0.302,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                 'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 2,
                                 5,
                                 0.494,
                                 0.207,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                 'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                 'float64, float64)',
                                 3,
                                 7,
                                 0.287,
                                 0.288,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                 'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 5,
                                 8.836,
                                 0.84,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                 'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 3,
                                 9,
                                 7.997,
                                 1.899,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                 'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, int64)',
                                 4,
                                 10,
                                 6.097,
                                 2.139,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._candidate',
                                 'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 1.299,
                                 0.738,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                 'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 6,
                                 12,
                                 0.561,
                                 0.561,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._descend',
                                 'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                 5,
                                 11,
                                 1.02,
                                 1.02,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                 'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 1.089,
                                 1.089,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                 'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                 'int64, int64)',
                                 5,
                                 11,
                                 0.55,
                                 0.55,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                 'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 1,
                                 4,
                                 8.343,
                                 7.071,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 2,
                                 17,
                                 0.57,
                                 0.57,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 2,
                                 17,
                                 0.702,
                                 0.702,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                 'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, float64, int64, array(float64, 3d, C))',
                                 0,
                                 None,
                                 0.648,
                                 0.264,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                 'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                 1,
                                 20,
                                 0.384,
                                 0.384,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.advance',
                                 'bench_myriapoda.bodies.fem.body_kernels.advance(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), array(float64, '
                                 '3d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                 'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                 '3d, C), array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                 'array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                 '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), int64, '
                                 'array(float64, 1d, C), array(float64, 1d, C), int64, array(float64, 3d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 48.894,
                                 10.184,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                 'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                 'float64, bool, array(float64, 3d, C), array(float64, 2d, C))',
                                 1,
                                 22,
                                 0.603,
                                 0.603,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 22,
                                 18.917,
                                 0.947,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                 'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 0.729,
                                 0.729,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 8.693,
                                 8.693,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 7.621,
                                 3.865,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                 'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 3,
                                 27,
                                 3.756,
                                 1.533,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                 'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                 'float64, float64, float64, float64, float64)',
                                 4,
                                 28,
                                 1.773,
                                 1.773,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                 'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64)',
                                 4,
                                 28,
                                 0.45,
                                 0.45,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                 'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), '
                                 'array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 0.928,
                                 0.928,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                 'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                 'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                 'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 1,
                                 22,
                                 5.076,
                                 0.924,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 2,
                                 32,
                                 4.153,
                                 4.152,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.segment_spines',
                                 'bench_myriapoda.bodies.fem.body_kernels.segment_spines(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C))',
                                 1,
                                 22,
                                 0.487,
                                 0.487,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                 'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 1,
                                 22,
                                 1.983,
                                 1.983,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                 'array(float64, 1d, C), float64, float64, float64)',
                                 1,
                                 22,
                                 9.555,
                                 7.224,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                 'int64, float64, float64, float64)',
                                 2,
                                 36,
                                 1.097,
                                 1.097,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_normal',
                                 'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 36,
                                 1.234,
                                 0.725,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                 'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                 'float64)',
                                 3,
                                 38,
                                 0.276,
                                 0.276,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                 'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 3,
                                 38,
                                 0.232,
                                 0.232,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                 'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                 'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64, float64)',
                                 1,
                                 22,
                                 0.938,
                                 0.938,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                 'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                 '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                 1,
                                 22,
                                 1.15,
                                 1.15,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity',
                                 'bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 1d, C), float64)',
                                 0,
                                 None,
                                 0.361,
                                 0.361,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.852,
                                 0.852,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                 'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '2d, C))',
                                 0,
                                 None,
                                 0.787,
                                 0.787,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                 'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 1.432,
                                 0.892,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                 'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 46,
                                 0.54,
                                 0.54,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                 'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), float64, '
                                 'array(bool, 1d, C))',
                                 0,
                                 None,
                                 1.134,
                                 1.134,
                                 False,
                                 True)]},
 'hybrid-legged-dry': {'args': 'eNrtHGuPG1fVu2t7H4QSpQ0NblmtRi1yo9GG7loo/oYbuiRy0g9RUSuVajQej/eO155xxmNnR6tKCClrkO4XmimEtKUvKFAK5VGJRwWE8pIiviD1K1K/RvAD+FbuuffOwzsz9trrXbqbySje+753zjn3nHPPPWe+ln7BupSi/5518nn8Gb3TrMjLimGqy5bdUtvLcqVtmbJiOfheCUokU1UMnZR1FMswnesOnlWMlm2q6w6+J1wZHlBv2TTh4EzJNGUbWs1VOlrD0nRSmDUqdZVMd915ouc85+RxpgrNHTSDsvhUaLS2IjdkEwZbaxgydEPHeMe0LjdVsrwaVHyhALNo1lWtaiGn/EWckRSjqjrlBzs957JDGle1plOextmGbBsd8rpT5xx3iJMyLDTPBxKXVqri0rlHHHeMS9en6SCwRDTvzo8+RfPH8ewF3VLXVTOwNnQSZzQdFoXuJ2vJtrV1Xa0630Cnyjk21APlafQg+ixaxPeyyWlzb2q0dMmJmTRH+s7wvjsXvur1fmFA76mY3o96vb/NelukyxlUhAeSBZZEghUeVwyM2/9G/qjf4WsqoWLPgXGQ0COdRZLMwWP1Z1gKWgwqgqQYkSGP6Bb4RbyCVeWin53D9PUZMByr4slc7PoCNSXyCN5T4H8JrCG3HVihAK39FgJFgXiNjif4Y/qoYsVF1s2bL/CKAOhtBk+h53UokCeKYtIxFFPwcHvTpxjBXzKDDuzsB0I7mzASS9Z0lW7uJzuthhrc3BnGQ2BhJbok5C1pIx8AW8yWfMwwGqqs92/JdIWUOmQPnnD3oEuxJ9h7QX2QYF/kBGt7D8OBTRdQjHwKtEXRa8/SBaS4WwdnFKOjW05Z5Mut4fmv6JqhPwlsMLBg8p42xQt0LhGULeJrtOEz4dWKkVtZjORrYiTTECNRK0Zs5WcBNC9x0Cw+/cFMKkXRl49oKy5FL2GSxX1wOMCyYatcHXfxY0Hw0bu5eHUPGIgZez8pY+wFDHuzwiSAyVZHGeDLfJdzuYK2ylnOtJ7z2RTaBibdA16QSadSjEUlHCHhCAlHOFocYaCSEVYRvuepCBfT/SpCzHw7qDxhIQkLSVjIEWMhk8AUVU1eCRg4anjhCbmpVneeIoluAtXPB49U7sHRPZ2xM/gZem4r0pPxVvk4ztY0tVEl5088pTh46oqDp7smSVx18PwGObQ2ZUsjFWlEWpHiTfK/S052NW1TJfk52bKkilG1SWtINgxFbjh4oaHpG5JuVME4lr7cBpPa9OUKSV+xmi2SrlrkAI3v0fS2JeuKKikNuU2aPlRRdQVJTdvU5JZRlZfJ0BqcoAl0NLVKZtqEEY+dY/nHaPY6MN7KVCoVLM1/fBjnaKNGcq9RWFqfeW2PW92dkBdQcnw1QI59popQARCdSAlOCFe6JrYSsyVQapyLULnBzkBVbrwWNAkMOf+vDhbYr7kCG78XKa1XJ89sB6NwHH5NsfG6d26JtxJ9LmAZynZ8ay06/U10qvzpnSai+9hsnZBV8w0+123KSkoUecFfZqzbKufCaMyjW9zAUyIEcRtsh2TTfnkq6hB1yLAwMYNU/9qiNnMUYkSao1T9fU8N/dd0jBo6hAXxkffASFYiVNrDhtCRBP14xZ3IdXd2z/zHEBOHYoDdgZGyox9ECyKm5/SAEc1EyBOiB20D4/98pDRZGSw33vTkxtrQM9tuXo++xw/jBKqrwBW5GlfwOOwnojgsN6FT8/kz+2c+p4D4kQeIj8bhMxPU8/eus4153glg8MdxGCzSWz5xoE2R1FOCFAapNz6Tf8uDvDHQ0NDHykesjT+L/GQwrRa9q7sSPWYU+G0bo9rjUVTLtQJKtV8dQcNbGUfve9uTkO2p8STkfpDo6qSPC2Nq+6uTeJnh/O6nrsoatyXy6L/1NMEP+g/6AH1I2y0+/XB2oK64f2QvJmRy4GQi3uVCRUyU90R5P7LKuzgZ3TlalaVy/meenD+ddeV8sqWSLXV0t9TShPbU0t0ueZcOWr1cSvTLg9cvBxxx32GyYxsOJ9PoBs7wS6eMgmRNh/K3sBBzT4XsiqlVl9mF2MJ5mruorvM7qpuzqZRflk+uq/b7usrdW4noT0R/IvoT0Z+I/kT0xyGDyv6fxxvyh12spwkczsK1+hw6DdFP9++MfjrhgetsMPjpF3zKAo/+CM7RDXdnZO93/6XXHWInmBvFfIRJtf4IGFSLLMKi/hDJUIv718P3RCsj3BONGlAhhmFAz+u/8i41/rE778mzuyTlSOLse8+9UWZhqIPGu8FwoQKNXCpRP3J2J8Ruf2hAlRuc5IY3RbjM8IAbiuUMwfIdArHOKPrFpFz66Kv9Om63BOKBYq+96G0l9et5fBJ3lZSMfuOR0XYQKP83v0MKpd/GXFOTncjPGGHgsLpFvBJ5ITZo11E4/M6Dw+ooxFHwF/0eH6HLQuyKoaA+uLGLyJYiIxR3BOeJnMyBOLrw9Bza0e7xTWKzK1N3YhZlB8xtpBBKfzeFgh794MAc60Y91XK9/j4QnXjNW1KRBfrFBzyWuK+lTdvYNPIQNrfobm7Bb81CGgU/wNIdwA2PFNnmyXNIsNBH5gE6R4gi5P8J0Yvg8LCIT7rVLmKXNpdWKVJ/z5Ba3wJR0A9AP8vnoo3oD1TYfkimtTMU060XWRAmINKP37Qp5oQ+AkC5ax4KBMrrAm8PS+gCCFkXFyC2yzxpxGgRIkYj/V1dd8NbnkPc7V24q93Io1fQqzirSzVTVR2ctlQLAri/1JQ0vUvyiqHWSL7ZaSsNqG9Sb9X0FekqNFuTrhrmBkmc54lZTVeklmXylFEjndMt1Ww6eL69YUs1zWxbpBLStFkGUhfJCLUWK4CEYjRYogsutdlWjVeRBKsiCVo1D462ErjcQnt3MRWWsMBe8fBge8WGaupqg7zK3Nrjly6ScbjB4sPpVMotSY7PyfH5qHqS/SEgop+P8SS7gV5Dr6M3eoPMf6a2rlUlZifECyXLkhXUVHX6LYdFXPYLJuI39sfoVQ/2GyOs7rvoJnoRvVT/FmHu+BjEpVuazJ34jyG5UZPUTYsssu2gl/EntWar02irkkKWroLjv2Eq5G/WMswrHZWyl/o7MFLG98bHHx2UUfNj7BR2Kw49YaewG3k8u27KXc2COApLNU1pQ9OrVBCZhOUv1ExNkZqEyxNun4YMyBNkt4Pgf8owG1UGfoOmD9Yz7E+DqXGYZxgBQaYmyRZ8NWCT/c1uSi2TBpmYalurdkDUZdotQrAOehNPXXbw9AWIUlEMIr1MImUdPNOAnTcj6+sEQKQXhJps6PAD41myua5a0EpuBiA3d84gIkYjfajQ60IkCS9JTDMH7Rz2vhfPIAY/xFLimmmOKIcFSjQQyST0fCWR6a+BTG7QV092Xyjweft1SMH9qEmRL0bY7lendw4TUUWK6++CKk56198Hdfuf8HOHGmqC54HwC7ERhzgMC9wbeKu8EOl2Smrp+fv8hLwu6dHzz97R89+Hypw8ZnHA0PMX/uY5ztxD2HE/ocP+52IjnnLcIfg+hhd3Lt8F+K8ejC/0HfS8i69AgrOA2Hwwsutvg5x7o9g2oav6FJDrIr4zPrYPIZf6u+/C6h1sKUxyrhUiN8T0MDoz8vf9brlatKWD2h9dQwnDqcJe4wxDb/Dk7WHbr/c+tiRypmZbjrr8P5e02uI=',
                       'case': 'centipede/hybrid/walk',
                       'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                   'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.62,
                                   0.62,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                   'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.178,
                                   0.178,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                   'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.335,
                                   0.335,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.271,
                                   0.271,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.301,
                                   0.301,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                   'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   0,
                                   None,
                                   12.24,
                                   0.578,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_phi',
                                   'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   1,
                                   5,
                                   6.109,
                                   0.337,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                   'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                   'float64)',
                                   2,
                                   6,
                                   0.227,
                                   0.228,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                   'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   2,
                                   6,
                                   0.394,
                                   0.142,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                   'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                   'float64, float64)',
                                   3,
                                   8,
                                   0.252,
                                   0.252,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                   'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   2,
                                   6,
                                   5.151,
                                   0.418,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                   'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                   'float64, float64, float64)',
                                   3,
                                   10,
                                   4.733,
                                   0.999,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                   'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, int64)',
                                   4,
                                   11,
                                   3.734,
                                   1.241,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._candidate',
                                   'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   0.838,
                                   0.455,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                   'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   6,
                                   13,
                                   0.383,
                                   0.383,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._descend',
                                   'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                   5,
                                   12,
                                   0.59,
                                   0.59,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                   'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   0.706,
                                   0.706,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                   'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                   'int64, int64, int64)',
                                   5,
                                   12,
                                   0.359,
                                   0.359,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                   'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   1,
                                   5,
                                   5.553,
                                   4.754,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   2,
                                   18,
                                   0.276,
                                   0.276,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   2,
                                   18,
                                   0.522,
                                   0.522,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.place_attached_nodes',
                                   'bench_myriapoda.bodies.rigid_chain.place_attached_nodes(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   1.01,
                                   0.574,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                   'array(float64, 3d, C))',
                                   1,
                                   21,
                                   0.436,
                                   0.172,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, float64, '
                                   'float64, array(float64, 2d, C))',
                                   2,
                                   22,
                                   0.265,
                                   0.265,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.974,
                                   0.234,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.side_sign',
                                   'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                   1,
                                   24,
                                   0.057,
                                   0.057,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                   'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   1,
                                   24,
                                   0.683,
                                   0.237,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_root',
                                   'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   2,
                                   26,
                                   0.335,
                                   0.164,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.matvec',
                                   'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   27,
                                   0.171,
                                   0.171,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                   'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   26,
                                   0.111,
                                   0.111,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                   'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, '
                                   '1d, C))',
                                   0,
                                   None,
                                   0.193,
                                   0.193,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                   'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                   'float64, array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.16,
                                   0.16,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 4d, C))',
                                   0,
                                   None,
                                   0.595,
                                   0.406,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                   'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                   '2d, C), float64, float64, array(float64, 2d, C))',
                                   1,
                                   32,
                                   0.189,
                                   0.189,
                                   False,
                                   True),
                                  ('bench_myriapoda.fused.legged_walk.legged_chunk',
                                   'bench_myriapoda.fused.legged_walk.legged_chunk(float64, float64, int64, '
                                   'Tuple(array(float64, 1d, C), array(int64, 1d, C), Tuple(array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                   'C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(float64, '
                                   '2d, C), array(float64, 3d, C), array(float64, 2d, C), array(bool, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(bool, 1d, C), array(float64, 3d, C), array(float64, '
                                   '4d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)), '
                                   'HybridLegs(CarriedBoxes(array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C), array(int64, 2d, C), array(float64, '
                                   '3d, C), array(float64, 3d, C), array(float64, 1d, C), float64), '
                                   'Tuple(Tuple(array(float64, 2d, C), array(float64, 2d, C), int64, array(int64, '
                                   '2d, C), array(float64, 3d, C), array(float64, 2d, C), Tuple(array(float64, 3d, '
                                   'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 3d, C)), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(uint64, 1d, C), '
                                   'array(uint64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                   'C), array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                   'array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C)), '
                                   'Tuple(array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C)), '
                                   'Tuple(array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(float64, 3d, C), array(float64, '
                                   '2d, C), array(float64, 2d, C)), Tuple(array(float64, 1d, C), int64, '
                                   'array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, 1d, C)), '
                                   'Tuple(array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                   'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C)), array(float64, 1d, C))), Tuple(array(float64, 1d, C), '
                                   'array(int8, 2d, C), array(float64, 3d, C), array(int64, 1d, C), array(bool, 2d, '
                                   'C), array(float64, 3d, C), array(float64, 3d, C), array(float64, 4d, C), '
                                   'array(float64, 3d, C)))',
                                   0,
                                   None,
                                   107.748,
                                   15.864,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.controller_step',
                                   'bench_myriapoda.controllers.myriapod.compiled.controller_step(array(float64, 2d, '
                                   'C), array(float64, 3d, C), float64, array(float64, 1d, C), array(int64, 1d, C), '
                                   'Tuple(array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(bool, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                   '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(bool, 1d, C), array(float64, 3d, C), array(float64, '
                                   '4d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   1,
                                   34,
                                   38.468,
                                   4.594,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                   'int64)',
                                   2,
                                   35,
                                   1.281,
                                   0.845,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                   'int64, int64)',
                                   3,
                                   36,
                                   0.436,
                                   0.436,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_step',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_step(array(float64, 1d, '
                                   'C), array(float64, 2d, C), float64, float64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), Tuple(array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C)), '
                                   'Tuple(array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C)), '
                                   'Tuple(array(float64, 3d, C), array(float64, 4d, C)), bool)',
                                   2,
                                   35,
                                   5.046,
                                   3.267,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                   'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                   '1d, C), array(float64, 1d, C), float64, float64)',
                                   3,
                                   38,
                                   0.164,
                                   0.164,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                   'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                   'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                   3,
                                   38,
                                   0.844,
                                   0.153,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                   'float64, float64, float64, float64, array(int64, 1d, C))',
                                   4,
                                   40,
                                   0.691,
                                   0.69,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                   'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                   'array(int64, 1d, C), int64, float64, float64, float64)',
                                   3,
                                   38,
                                   0.168,
                                   0.168,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   38,
                                   0.427,
                                   0.427,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                   'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                   '2d, C), float64, float64, float64)',
                                   3,
                                   38,
                                   0.176,
                                   0.176,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.tips_touching',
                                   'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   0.828,
                                   0.828,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                   'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                   2,
                                   35,
                                   0.098,
                                   0.098,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                   'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                   '1d, C), int64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   0.22,
                                   0.22,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                   'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, '
                                   'C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                   2,
                                   35,
                                   9.352,
                                   1.995,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                   'array(float64, 1d, C), float64, float64, float64)',
                                   3,
                                   48,
                                   5.915,
                                   4.953,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_normal',
                                   'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   4,
                                   49,
                                   0.962,
                                   0.438,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                   'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                   'float64, float64)',
                                   5,
                                   50,
                                   0.31,
                                   0.31,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                   'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   5,
                                   50,
                                   0.215,
                                   0.215,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                   'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64, float64)',
                                   3,
                                   48,
                                   0.735,
                                   0.313,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                   'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                   'float64, float64)',
                                   4,
                                   53,
                                   0.249,
                                   0.113,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                   'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                   'float64)',
                                   5,
                                   54,
                                   0.136,
                                   0.136,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                   'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                   '2d, C), int64, float64)',
                                   4,
                                   53,
                                   0.173,
                                   0.173,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                   'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64)',
                                   3,
                                   48,
                                   0.199,
                                   0.199,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                   'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, '
                                   'C))',
                                   3,
                                   48,
                                   0.507,
                                   0.507,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                   'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                   '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   35,
                                   4.549,
                                   0.96,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   3,
                                   59,
                                   3.493,
                                   3.493,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   59,
                                   0.095,
                                   0.095,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                   'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                   'C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   1.374,
                                   0.734,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                   'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                   3,
                                   62,
                                   0.058,
                                   0.058,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                   'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                   3,
                                   62,
                                   0.095,
                                   0.095,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                   'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   62,
                                   0.172,
                                   0.173,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                   'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                   3,
                                   62,
                                   0.092,
                                   0.092,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                   'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, '
                                   'C), int64, float64, float64, float64, float64)',
                                   3,
                                   62,
                                   0.223,
                                   0.223,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(bool, 1d, C))',
                                   2,
                                   35,
                                   4.158,
                                   1.023,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3), '
                                   'float64)',
                                   3,
                                   68,
                                   1.915,
                                   1.354,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                   'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   4,
                                   69,
                                   0.562,
                                   0.562,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3))',
                                   3,
                                   68,
                                   1.219,
                                   1.219,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                   'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   35,
                                   0.476,
                                   0.317,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_tip',
                                   'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), float64, float64, float64, float64)',
                                   3,
                                   72,
                                   0.159,
                                   0.159,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                   '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                   2,
                                   35,
                                   1.258,
                                   1.258,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                   'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   35,
                                   3.6,
                                   3.036,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                   'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   75,
                                   0.134,
                                   0.134,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._wrap',
                                   'bench_myriapoda.kinematics.legs._wrap(float64)',
                                   3,
                                   75,
                                   0.077,
                                   0.077,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._ik_solve',
                                   'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                   'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                   3,
                                   75,
                                   0.353,
                                   0.353,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, '
                                   'C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                   2,
                                   35,
                                   1.637,
                                   1.637,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                   'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                   '3d, C), float64, array(float64, 1d, C))',
                                   2,
                                   34,
                                   1.194,
                                   0.518,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                   'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, 2d, '
                                   'C), array(float64, 1d, C))',
                                   3,
                                   80,
                                   0.675,
                                   0.675,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.advance_chain',
                                   'bench_myriapoda.bodies.rigid_chain.advance_chain(FEMLinks(array(float64, 2d, C), '
                                   'array(float64, 2d, C), int64, array(int64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), Tuple(array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C)), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C)), Attachment(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C)), Boxes(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), array(bool, '
                                   '1d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C)), '
                                   'World(array(float64, 1d, C), int64, array(float64, 1d, C), int64, array(float64, '
                                   '1d, C), array(float64, 1d, C)), Coupling(array(float64, 2d, C), array(float64, '
                                   '2d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(int64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C)), array(float64, 1d, C), int64)',
                                   2,
                                   34,
                                   50.966,
                                   23.298,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                   'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, '
                                   'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, bool, array(float64, 3d, C), array(float64, 2d, '
                                   'C))',
                                   4,
                                   82,
                                   0.421,
                                   0.421,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                   'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   0.318,
                                   0.318,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   4.393,
                                   4.393,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   3.677,
                                   1.674,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                   'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   86,
                                   2.003,
                                   0.839,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                   'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   87,
                                   0.957,
                                   0.957,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                   'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   87,
                                   0.208,
                                   0.208,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                   'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   2.321,
                                   0.617,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   5,
                                   90,
                                   1.704,
                                   1.704,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                   'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                   'array(float64, 2d, C))',
                                   4,
                                   82,
                                   0.236,
                                   0.236,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                   'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                   '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   82,
                                   0.558,
                                   0.558,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                   'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                   'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   82,
                                   0.775,
                                   0.775,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.rigid_segments_step',
                                   'bench_myriapoda.bodies.rigid_chain.rigid_segments_step(Attachment(array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 2d, C)), array(float64, 2d, C), '
                                   'array(float64, 2d, C), Boxes(array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), array(float64, '
                                   '3d, C), array(float64, 2d, C), array(float64, 2d, C)), World(array(float64, 1d, '
                                   'C), int64, array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, '
                                   '1d, C)), Coupling(array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                   'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C)), array(float64, 1d, C))',
                                   3,
                                   82,
                                   14.968,
                                   4.544,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                   'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   95,
                                   0.547,
                                   0.415,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._cross',
                                   'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                   'float64, float64)',
                                   5,
                                   96,
                                   0.132,
                                   0.132,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._step_body',
                                   'bench_myriapoda.bodies.rigid_kernels._step_body(int64, Tuple(array(float64, 2d, '
                                   'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C)), float64, '
                                   'array(float64, 1d, C), int64, array(float64, 1d, C), Tuple(float64, float64, '
                                   'float64, int64, float64, int64, float64, float64), Tuple(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(int64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                   'array(float64, 1d, C))',
                                   4,
                                   95,
                                   9.877,
                                   7.314,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                   'C), float64, float64, float64, array(float64, 2d, C))',
                                   5,
                                   98,
                                   0.265,
                                   0.265,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                   'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                   5,
                                   98,
                                   0.233,
                                   0.233,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                   'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, 2d, '
                                   'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   98,
                                   0.212,
                                   0.212,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   0.556,
                                   0.556,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   0.352,
                                   0.352,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                   'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   0.605,
                                   0.275,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                   'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64)',
                                   6,
                                   104,
                                   0.33,
                                   0.229,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                   'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                   'float64, float64, float64, float64)',
                                   7,
                                   105,
                                   0.101,
                                   0.101,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                   'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                   'float64)',
                                   5,
                                   98,
                                   0.147,
                                   0.147,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                   'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                   5,
                                   98,
                                   0.193,
                                   0.193,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.finish_chunk',
                                   'bench_myriapoda.controllers.myriapod.compiled.finish_chunk(array(float64, 1d, '
                                   'C), array(int64, 1d, C), Tuple(array(int64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(int64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 1d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), array(float64, '
                                   '3d, C), array(float64, 4d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C)))',
                                   1,
                                   34,
                                   1.258,
                                   0.752,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, '
                                   'C), float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, '
                                   'C), array(float64, 4d, C))',
                                   2,
                                   109,
                                   0.506,
                                   0.506,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                   'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.501,
                                   0.501,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.energy',
                                   'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.429,
                                   0.429,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                   'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.497,
                                   0.497,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                   'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                   'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   0,
                                   None,
                                   0.579,
                                   0.579,
                                   False,
                                   True)]},
 'hybrid-legless-dry': {'args': 'eNrtGUuP20R4H0l2t5RStRRK2q5WlkABWVu6jZByIy0sVGl7qIq6qK1cx57sTOPY6Xi8uzkgcdoFaS5QF7G8368TdyQOPfIfqPgBXPgF5Zvx2HESJ91HKSo0lpxvvpn55pvvPZ63c7d+PjYmf1fDUok/4watujlveRTNs04b+fNm3WfUtFjIDxoCY1BkeS7gAot5NLwZ8inLa3coWg75vsHOQYJuuyOBkOerlJodMWq6HhCHEReQBa9+HcFyN8PzG+FbYYnnbTE8xJO4wA8PUPMt0zGpILboeKaYhveqiTnXbCFgryE6XiqLVQhbJTbDYe1lnjcsz0Zh7WiwEV4IYbBNWmFtghccs+MFsN3x02FM4pApGC0pQvrcgq3PnX4+jGmce29CEhEs4pl4ffyEbO/nU2dchpYRTfGGD/E8cQVT+GngpeCTZRfZ4Tv4cK0YkTpSm8BH8TE8yw9Gi8vhydJ47tz7QxYtwtxJNbef8ZPJ7JsjZo8PmX0imR1GsxlMOY4r4hFgOQKxxgbp6im6vTvqUr2leKriykYo6GBtAybrABbFw3obESRGjEIJUM9owKPHiC5KdURdxeynn0zPnBHkoi4FFofyl+qpwqMlT1n9g6xFaz3FoSZGCwc5MuAg4I/MJC6SPnIxaDso7SP5yBVLkrAOyhSLCN29mejuSlexVfkug3PkLS9wWVibVlZ+ic+84RLPvShcNWXnV8R4XAV1zvJFOeJyplHpmYaqZxjKVWEpHypLmeW/yC2VsqfPZa+1I3QPE7ukHLEnbX5T7aSilJsVQp5LhY1C0I0b+IV3IWA8FQeM2L2ejFYLBvzrI7VWIA2rKhWafmvSc6/VimrdetoGmpJF0CUYSSCsGM8uvTY+NhYp9SHWgr4lg1zYppnqGVFbz1KMLlvSqj+OrXrp94mxsUyRLmRvJUYryllrz21NOfHoh1mhWxy+sAt0kMl3NnaXyO0I7t8nsDUxynD0SaoESaWbKOttiEA0ORiIIAZV10XgfzEzmyyMzhufJnljMW3gOxBFah+fZe+jlCTuytDIDsXhKc9zkOn2Foe5OmBDCO4H+oP7gYgP0Z8O7Z8rHspJEH8sK4hvRkFcBG9+OS3ANL3dB0Qp6y8SWd/dSSjbFXo3Ht8jim1GzeFG8uUwI6nIklaPamjQWyHD5qFf2rw2qoLq5pGvEsl7mZI/kZUtttmbiZY7/Xq0O1SSSrYK/2VZW2rq0HCttj/LalXhIa32yjaKyIWdlJbfJEnYH99ZEv4nTPTkLpYcHchO3g/0ifu3dWlD3yZVsa5ONnDC2HMeDuN2/xEmtqz48NJMSung3oUuLzQIcmw4APHxNTjyr4S84BoNiuDQn2OIie8Rr7QM4kJHzvJQA9qtwLcc0d8yfejP3TBWxbBFY9WjTQBeV8AUcS2jzaiCvAZMzrURbYV8xm92jAahPpykpgQsh+UFdBYoNNoRQgAW5AEJrJgCaDdUFwBRFwCya8b1bGQ4xBU8NGJm6hEA6+wjrs9M10KG5UjGn60j18JGq0OJ2fZsc77u2QQOjLhTp8SebyLqIgfGTS++eu4skPWF0GeX/oDSNMY8qk4fVaf/1er0u1Qa+3VIdXqb5xtkDdngJCZjBjhQBxxRgI5ngVPCsDtcG+JnlCwT27CwSdyQ76kyZlq4hVz5CXOW17qI+1Kkfp+9nf4idbOngrwNYdGCsHgj5BMrEHXGV0P8G98rviYxYqr97sWm0zDQGgNWIVzMNKG7ZTICEx8nrXbg+BByYCsQMvMNj1rwX2AevREgCEv4Dv6T5095aygKL/yuhP/fteIPw3Q1WCuChqaWqblCmLA8hig1QP62zF4UNLanQYlltCA1QIrIiYZIQrjjJ7K/5FHHjmTvSfjBVos/jrbLe1WLsP98wwCPA+Nai/4La0abSp+kyCd2IJJj3m+DVYIVX6iDFV8A4MwqyMvyIMdRSM0hn3SEG06a7jIICCa2YUzTFS9Bkpl0GTExymzFkps+7UEWIjBB5sUVqBZjzKOC8UEXjD/1Foy9H6w1XMQfCDOSH86PR7cKKu5FdwqpRnHUZ/+tIzW1bm8BqsVf9SuKGW09facxcMXRdzmg3+OmI0Won5+MLoH+S/BwPQe2e/2geOnwii5zUjcPfZvsEVlSbQs/LaroFF97FBXzGf4bLaKl7y+0ZG/FeG/FZMRomY9Qw/D+7l62qu8UKs2lJo8elXgXXbkkqOOxRUZNXUlpMz2hDMlXCVGaRmVddVYSXUTRUJJB838Dg7Z2jw==',
                        'case': 'chain/hybrid/fig4-drop',
                        'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                    'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.892,
                                    0.892,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                    'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.258,
                                    0.258,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                    'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.566,
                                    0.566,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.409,
                                    0.409,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.474,
                                    0.474,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                    'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    0,
                                    None,
                                    20.857,
                                    0.85,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_phi',
                                    'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    1,
                                    5,
                                    11.344,
                                    0.579,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                    'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                    'float64)',
                                    2,
                                    6,
                                    0.368,
                                    0.368,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                    'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                    'float64, float64)',
                                    2,
                                    6,
                                    0.726,
                                    0.254,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                    'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                    'float64, float64)',
                                    3,
                                    8,
                                    0.472,
                                    0.472,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                    'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    2,
                                    6,
                                    9.671,
                                    0.558,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                    'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                    'float64, float64, float64)',
                                    3,
                                    10,
                                    9.112,
                                    1.277,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                    'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, int64)',
                                    4,
                                    11,
                                    7.835,
                                    3.152,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._candidate',
                                    'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    1.36,
                                    0.743,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                    'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    6,
                                    13,
                                    0.617,
                                    0.617,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._descend',
                                    'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                    5,
                                    12,
                                    0.978,
                                    0.978,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                    'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    1.486,
                                    1.486,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                    'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                    'int64, int64, int64)',
                                    5,
                                    12,
                                    0.861,
                                    0.861,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                    'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                    'float64, float64, float64, float64)',
                                    1,
                                    5,
                                    8.662,
                                    7.339,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    2,
                                    18,
                                    0.665,
                                    0.665,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                    'C), float64, float64, float64, float64)',
                                    2,
                                    18,
                                    0.659,
                                    0.659,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_chain.place_attached_nodes',
                                    'bench_myriapoda.bodies.rigid_chain.place_attached_nodes(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.161,
                                    0.767,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                    'array(float64, 3d, C))',
                                    1,
                                    21,
                                    0.394,
                                    0.169,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                    'float64, float64, array(float64, 2d, C))',
                                    2,
                                    22,
                                    0.225,
                                    0.225,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.hybrid.kernels.advance',
                                    'bench_myriapoda.bodies.hybrid.kernels.advance(Tuple(array(float64, 2d, C), '
                                    'array(float64, 2d, C), int64, array(int64, 2d, C), array(float64, 3d, C), '
                                    'array(float64, 2d, C), Tuple(array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C)), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C)), Tuple(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 2d, C)), Tuple(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(bool, 1d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C)), Tuple(array(float64, 1d, C), int64, array(float64, 1d, '
                                    'C), int64, array(float64, 1d, C), array(float64, 1d, C)), Tuple(array(float64, '
                                    '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(int64, 1d, C), array(float64, 3d, C), '
                                    'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                    'array(float64, 1d, C), int64)',
                                    0,
                                    None,
                                    101.142,
                                    5.567,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_chain.advance_chain',
                                    'bench_myriapoda.bodies.rigid_chain.advance_chain(FEMLinks(array(float64, 2d, '
                                    'C), array(float64, 2d, C), int64, array(int64, 2d, C), array(float64, 3d, C), '
                                    'array(float64, 2d, C), Tuple(array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C)), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C)), Attachment(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 2d, C)), Boxes(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(bool, 1d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C)), World(array(float64, 1d, C), int64, array(float64, 1d, '
                                    'C), int64, array(float64, 1d, C), array(float64, 1d, C)), '
                                    'Coupling(array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                    'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C)), array(float64, 1d, C), int64)',
                                    1,
                                    24,
                                    95.574,
                                    36.546,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                    'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, '
                                    'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), float64, bool, array(float64, 3d, C), array(float64, 2d, '
                                    'C))',
                                    3,
                                    25,
                                    0.29,
                                    0.29,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                    'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    0.298,
                                    0.298,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    5.728,
                                    5.728,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    7.437,
                                    2.576,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                    'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    4,
                                    29,
                                    4.861,
                                    1.412,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                    'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    5,
                                    30,
                                    2.792,
                                    2.792,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                    'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    5,
                                    30,
                                    0.657,
                                    0.657,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                    'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, '
                                    'C), array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    5.499,
                                    2.482,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    4,
                                    33,
                                    3.016,
                                    3.015,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                    'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                    'array(float64, 2d, C))',
                                    3,
                                    25,
                                    0.538,
                                    0.538,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                    'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, '
                                    'C), float64, float64, float64, float64)',
                                    3,
                                    25,
                                    1.417,
                                    1.417,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                    'array(float64, 1d, C), float64, float64, float64)',
                                    3,
                                    25,
                                    8.747,
                                    6.493,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    4,
                                    37,
                                    0.689,
                                    0.689,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_normal',
                                    'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    4,
                                    37,
                                    1.564,
                                    0.616,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                    'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                    'float64, float64)',
                                    5,
                                    39,
                                    0.572,
                                    0.572,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                    'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    5,
                                    39,
                                    0.376,
                                    0.376,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                    'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                    '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    25,
                                    0.977,
                                    0.977,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                    'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                    'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    25,
                                    1.218,
                                    1.218,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_chain.rigid_segments_step',
                                    'bench_myriapoda.bodies.rigid_chain.rigid_segments_step(Attachment(array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 2d, C)), array(float64, 2d, C), '
                                    'array(float64, 2d, C), Boxes(array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), '
                                    'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C)), '
                                    'World(array(float64, 1d, C), int64, array(float64, 1d, C), int64, '
                                    'array(float64, 1d, C), array(float64, 1d, C)), Coupling(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(int64, 1d, C), array(float64, 3d, C), '
                                    'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                    'array(float64, 1d, C))',
                                    2,
                                    25,
                                    26.881,
                                    8.931,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                    'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    44,
                                    0.94,
                                    0.775,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._cross',
                                    'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                    'float64, float64)',
                                    4,
                                    45,
                                    0.166,
                                    0.166,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._step_body',
                                    'bench_myriapoda.bodies.rigid_kernels._step_body(int64, array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), float64, '
                                    'array(float64, 1d, C), int64, array(float64, 1d, C), float64, float64, float64, '
                                    'int64, float64, int64, float64, float64, array(float64, 2d, C), array(float64, '
                                    '2d, C), array(int64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                    'array(float64, 3d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C))',
                                    3,
                                    44,
                                    17.009,
                                    12.73,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                    'C), float64, float64, float64, array(float64, 2d, C))',
                                    4,
                                    47,
                                    0.306,
                                    0.306,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.matvec',
                                    'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    4,
                                    47,
                                    0.271,
                                    0.271,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                    'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                    4,
                                    47,
                                    0.239,
                                    0.239,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                    'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                    '2d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    4,
                                    47,
                                    0.235,
                                    0.235,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    4,
                                    47,
                                    0.593,
                                    0.593,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    4,
                                    47,
                                    0.47,
                                    0.47,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                    'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    4,
                                    47,
                                    0.353,
                                    0.353,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                    'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    4,
                                    47,
                                    1.291,
                                    0.435,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                    'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    5,
                                    55,
                                    0.856,
                                    0.661,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                    'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                    'float64, float64, float64, float64)',
                                    6,
                                    56,
                                    0.194,
                                    0.194,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                    'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                    'float64)',
                                    4,
                                    47,
                                    0.252,
                                    0.252,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                    'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                    4,
                                    47,
                                    0.27,
                                    0.27,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                    'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    2.86,
                                    2.86,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.energy',
                                    'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    1.109,
                                    1.109,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                    'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.901,
                                    0.901,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                    'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                    'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                    0,
                                    None,
                                    1.177,
                                    1.177,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                    'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.943,
                                    0.949,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                    'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                    '2d, C), array(float64, 1d, C))',
                                    1,
                                    64,
                                    0.994,
                                    0.994,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.hybrid.kernels.momenta',
                                    'bench_myriapoda.bodies.hybrid.kernels.momenta(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.355,
                                    1.355,
                                    False,
                                    True)]},
 'massspring-legged-dry': {'args': 'eNrtW91vI1cVdxw7H7tLu7QsLW6JLAvJprIidxOh8gRt5IqNd/uwFLHaEg3j8Th3EntmdjzeTR4qIaRNWOk+gDJpofRjJSS2tHwIWollEWrLV4ECT5X4A3hCVELilYflnHvvfDhzx06yTvoRZ5Tkzv2+55x77jnn/uYbme1vfyHFfpa8Ev2U2W3X1VnNcvRZd93WO7NqveM6quZ69F4FcxRH1ywT8rqaaznelkcnNcted/Rlj94VL4x3aNrrLOHR7KOOo65jral612i5hgmZE1Z9RYfhtrwnNr2nYUrZBlb3yDiZoPfHeutoakt1sLPHW5aKzcgJ0TBjqm0dptfEgs/N4yiGe8VouMSrfZFmFc1q6F7twe6md96Dyg2j7dXG6ERLXbe6sNyxBc/v4pSKEy2Jjsr5hxvl/MJnPb+Pc8+kWSc4RTLtj0/uJjnyQC1NHiSfJjOxPk7zPkj+3JZoXdyERtjFSTp5xnT1Zd2JLIecolnDxHWQ+2D6Ex1j2dQb3rfI/bUcb1+A8eBxoW4lfOEp7LpfFiYrkhd4Kn5GmCUKeFFO/uzspqdNn+54kUjmEucXKdlJ9QpQfUxQ/V5OdUa4gG9A82cFzaukGDwy7o0ncG8u6Gnb5x57Ci6mFjcidCniHCEvHAnqVK6yVRTDlUCqgM397AJvFqwyQlhk7wbnYnEzaLAIj2wJmYQlzAdLeI4vIRyw6A9YYbvugdiug03uqoaps433ZNdu6dGNl+X7GydWZVNSginVSxGS75ytkP3HLKulq2av7GfqkOuBsN/DyR2y+B6+LiyPcvj7gi928HAe2GwCBemzyGoUgvo8vUguslKgCs1qVtd0vVpZTHeJTn/FNCzzSVRRkQnDOm3GF2xcBZbN0Kus4lPx2Zal2qUs1RdlqRyWpawtS2R/CUnzvCDNzIV3x1Mpxr6SpG45L5/CMLN76HCIeYNmObffye+Lgg8f5ey5O+BAQt8HKRn7nsCglc0Pg5h8dkwBvpD2zQJ2mBCnNiGUlhuqKfI0KulN1AXZTCrFVdRII4w0wkgjfLQ0Ql8jI24ivBiYCGczvSZCwng7pHykQkYqZKRCPmIqZBicYqbJS5F4yRI99oTa1htJXiSrdC3qWPnuo++jVZlHJ4sCpKVRgDDy4ol5oN9XYJ61UztJJ5qG3mqA/0rHNI+OXfJo+rIDiSsenV4Fp7etugYUZAjUguw1+L0MnmHTWNPhfUp1XaVuNdahNiZblqa2PHqsZZirimk1MPCVOd/BcFn6fB3Sl9y2DemGCw44vcswO65qarqitdQOVP1MXTc1orTXHUO1rYY6C10b6IHDkgy9ASOtYY8nFvj7Y+x1CxV3fSyViuaWPjiKd2+9SrXfXlRiD9/vUFX4A4oMJkbXI+IchjpoKZ6B4lphYZEq2RJBh2hY4Xg02hmx0ykP8mCjihuEJb8ejSjsJXzQSzwZkdjbUhjh/JNY4k36ntQYGMBI0fleLIjBmQd57gV+1K1zf5Zyt87VziaqjHGJXwXM2sCoT0XKo9P9ra8f+tYXfXygIbWbjcCk9IZ8HaE+LQituihilE7teHxhQVyLxbSeOriYFiPEywEhbu9H7IZ4+N65ItynERLh4I+SOFhgSqXS19GHciaQhX5KQ2x7GOuVgPJWX+u//87ezb6XGQiv9pfVQhBPr7Kze1GEwLnUnpRJLW/CI7Ff26/elIdd4/v3x4H31BlL8J7eBxGdG/YZvM8jdG4Yixms737ix7+A56/Blng9fqb+k/yH/IO8Qd5hlW5emJeGwA5B5ssjGTl0GSkf8ROlfJQMufJw7Ci5WbOEZuJffAv5wueDiNmRonB+SCTOH/V9mT/swyc/On0O//RJtH5vnXuHq5INtFvSQTiKZkWsJ6sR1TChOB4teighWtSG0o7tGObyrF/m0bu/zHIWsLez+jILG9288NNsKrWjoDQKIx10GMnfg6MTY3RijE6M0YmxhxODHRl/Sw4NyVB2D0WRdUCHRxBUOkVmEU16nw+wS/cC7LBa9PLk58HlSTU2RjvenIt92PwXkbuXiyyc6NSmJZGblU+OpVIMm3eRVFc+Di8shvPNeOTx9B4ij3vFzZXjNGCRnteCMNlfd3dJ/sguRVkqnD3rvDPJnO9XmzHo9SgqdJEBVKsMLsSjjDyeyNC6PgbVR7HGhDDAVTIuZ4HL7wLFulKKHfDNLVvaL5N2SwT2mRhIZfFvREzR6jCi30yMbgZitBElyvt2vcyo9KuEiw/YiRtInLSEOLxshp6Whlj77TpGh1sBHeb2Ihzz4aR/LXpocyR1IYYYxxiw5LUqhb/vwGBXhJijcLTx2fRYQ3tTbBKbB+H9gTmYGpVbDyR/ED4/3E0xRH2IAc/xZuxCMbfZ2wZB6FeDKRU4njsZTV8Vl+k2q2MzgDlu7oq/uYthbY5cL4bofb+DoojJV/jmKQlKcIQ7v+ifAqHYec3PQOp4hTZDT/nFPmPza/k5xtTfcKauEDwKegkYvoqxWCX2BwvsEHnv7kTc++UVjrVHRoYwfZtxrtgjACR3NWBBkem6yOpxCm0kIW/iE8T2lSf7MKCwIb5XuLaLW2Hw/o6T/5XI8+QFOmEqTUfXPZppM0cvw9+mEVCgILTAo5PcwYPC6Y5rNJumjhUnG2rbhmxo4ugd1wN3UrliOaug18ntlRSQiR7n7t5Z6IX7gPS/kZwjdNP794jCu5Zw07tNXiQvkevwdoMWErxtx1g2Ggr30umxR11X1UhbN9nHSTO0FmYM5V73Dfms+9/rbpfIM+RZ8l3yPV+iTuDnHK6hCuzKCaK2moq+5sI0Ox55jn7MaNvdVkdXNJi8jngXy9Hg/4RrOZe6OsrTjRWK8pQNQSj09mHFDD7A17ZvJjEofm27XaKTy4562XARPuTqjqOsGmYDNi+mQZiajqEpbdj0LaYDGA7JJuudKPm/ajmtBie/xdKHe3f7Vn95HHR3CyTINhXVRVTMGv8/sabYDsNWgQozGl3EU2U7oNV0j/yAjp33aPoMgrM0ywEZVqymR8dbuPfGVV/xIcJq1cQ/2J+rOsu6i7XUdoRyUwsWHD+oLBmA6jICqETOyNU97Ovb3wafL1T8EzV6NsL7Rq8dsNNUkhRB9sp30IaA1ivX0U74Gf55m3mYUUOmGH4C19PjAOxMUQBjnNoxKQIDSpnj8KUhARCYzfy7wGb+94cqDrbP7IiH+nux8pzQojHu+B+W8l+O75yScCYnsDGf4HzxxwrRMH8IaHymx0INAriRhNhrie9R5OAf++FcZPoR5eo9mMa/9s/qD6EueDuEcgTmOCNIzvedcgMcpj5ZCZnhpk8s2pV/xqImvnvHGXox6iIE3OVeVcX3wfTZ/wMKesNj',
                           'case': 'centipede/massspring/walk',
                           'events': [('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.444,
                                       0.444,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                       'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       0,
                                       None,
                                       11.54,
                                       0.538,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_phi',
                                       'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       1,
                                       1,
                                       5.696,
                                       0.404,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                       'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                       'float64, float64)',
                                       2,
                                       2,
                                       0.178,
                                       0.177,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                       'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       2,
                                       2,
                                       0.343,
                                       0.13,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                       'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                       'C), float64, float64)',
                                       3,
                                       4,
                                       0.214,
                                       0.214,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                       'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       2,
                                       2,
                                       4.77,
                                       0.372,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                       'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       6,
                                       4.398,
                                       0.86,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                       'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                       'int64, float64, float64, float64, float64, int64)',
                                       4,
                                       7,
                                       3.538,
                                       1.194,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._candidate',
                                       'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       0.774,
                                       0.466,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                       'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       6,
                                       9,
                                       0.308,
                                       0.308,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._descend',
                                       'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                       'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                       5,
                                       8,
                                       0.563,
                                       0.563,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                       'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       0.619,
                                       0.619,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                       'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                       'int64, int64, int64)',
                                       5,
                                       8,
                                       0.387,
                                       0.387,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                       'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       1,
                                       1,
                                       5.306,
                                       4.538,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       2,
                                       14,
                                       0.334,
                                       0.334,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       2,
                                       14,
                                       0.435,
                                       0.435,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.place_attached_nodes',
                                       'bench_myriapoda.bodies.rigid_chain.place_attached_nodes(array(int64, 1d, C), '
                                       'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C))',
                                       0,
                                       None,
                                       1.286,
                                       0.918,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                       'array(float64, 3d, C))',
                                       1,
                                       17,
                                       0.368,
                                       0.145,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                       'float64, float64, array(float64, 2d, C))',
                                       2,
                                       18,
                                       0.223,
                                       0.223,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, '
                                       'C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       1.143,
                                       0.303,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.side_sign',
                                       'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                       1,
                                       20,
                                       0.079,
                                       0.079,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, '
                                       'C), array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                       'C))',
                                       1,
                                       20,
                                       0.762,
                                       0.315,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_root',
                                       'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                       2,
                                       22,
                                       0.312,
                                       0.162,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.matvec',
                                       'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                       'float64, float64)',
                                       3,
                                       23,
                                       0.151,
                                       0.151,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                       'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                       'float64, float64)',
                                       2,
                                       22,
                                       0.135,
                                       0.135,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                       'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, '
                                       'array(float64, 1d, C))',
                                       0,
                                       None,
                                       0.247,
                                       0.247,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                       'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, '
                                       'C), float64, array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.205,
                                       0.205,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       0,
                                       None,
                                       0.719,
                                       0.495,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                       'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                       '2d, C), float64, float64, array(float64, 2d, C))',
                                       1,
                                       28,
                                       0.224,
                                       0.224,
                                       False,
                                       True),
                                      ('bench_myriapoda.fused.legged_walk.legged_chunk',
                                       'bench_myriapoda.fused.legged_walk.legged_chunk(float64, float64, int64, '
                                       'Tuple(array(float64, 1d, C), array(int64, 1d, C), Tuple(array(int64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, '
                                       '1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(bool, 1d, C), array(int64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(float64, '
                                       '2d, C), array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C)), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C)), '
                                       'SpringChainLegs(CarriedBoxes(array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), '
                                       'array(int64, 2d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 1d, C), float64), Tuple(Tuple(array(float64, 2d, C), '
                                       'array(float64, 2d, C), int64, array(float64, 1d, C), array(int64, 1d, C), '
                                       'array(int64, 1d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                       'Tuple(array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C)), '
                                       'Tuple(array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(bool, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C)), Tuple(array(float64, 1d, C), '
                                       'int64, array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, '
                                       '1d, C)), Tuple(array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                       '2d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C)), array(float64, 1d, C))), Tuple(array(float64, 1d, '
                                       'C), array(int8, 2d, C), array(float64, 3d, C), array(int64, 1d, C), '
                                       'array(bool, 2d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 4d, C), array(float64, 3d, C)))',
                                       0,
                                       None,
                                       94.48,
                                       15.27,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.controller_step',
                                       'bench_myriapoda.controllers.myriapod.compiled.controller_step(array(float64, '
                                       '2d, C), array(float64, 3d, C), float64, array(float64, 1d, C), array(int64, '
                                       '1d, C), Tuple(array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                       'C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(bool, 1d, C), array(int64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 3d, C), array(float64, 4d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                       1,
                                       30,
                                       39.998,
                                       5.245,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, '
                                       'C), int64)',
                                       2,
                                       31,
                                       1.253,
                                       0.844,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, '
                                       'C), int64, int64)',
                                       3,
                                       32,
                                       0.408,
                                       0.408,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_step',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_step(array(float64, '
                                       '1d, C), array(float64, 2d, C), float64, float64, array(float64, 1d, C), '
                                       'array(float64, 1d, C), Tuple(array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C)), '
                                       'Tuple(array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C)), '
                                       'Tuple(array(float64, 3d, C), array(float64, 4d, C)), bool)',
                                       2,
                                       31,
                                       5.795,
                                       3.496,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                       'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                       '1d, C), array(float64, 1d, C), float64, float64)',
                                       3,
                                       34,
                                       0.213,
                                       0.213,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                       'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, '
                                       '1d, C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       3,
                                       34,
                                       1.105,
                                       0.185,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, '
                                       'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       4,
                                       36,
                                       0.92,
                                       0.92,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                       'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, '
                                       'C), array(int64, 1d, C), int64, float64, float64, float64)',
                                       3,
                                       34,
                                       0.193,
                                       0.193,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       34,
                                       0.547,
                                       0.547,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                       'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                       '2d, C), float64, float64, float64)',
                                       3,
                                       34,
                                       0.241,
                                       0.241,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.tips_touching',
                                       'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       0.693,
                                       0.693,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                       'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, '
                                       'bool)',
                                       2,
                                       31,
                                       0.092,
                                       0.092,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                       'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                       '1d, C), int64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       0.205,
                                       0.205,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                       'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, '
                                       'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'float64, float64, float64, float64, array(float64, 2d, C), array(float64, '
                                       '3d, C))',
                                       2,
                                       31,
                                       9.277,
                                       2.162,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                       'array(float64, 1d, C), float64, float64, float64)',
                                       3,
                                       44,
                                       5.708,
                                       4.497,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_normal',
                                       'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       4,
                                       45,
                                       1.211,
                                       0.334,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                       'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                       'float64, float64)',
                                       5,
                                       46,
                                       0.272,
                                       0.272,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                       'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       5,
                                       46,
                                       0.605,
                                       0.605,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                       'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       3,
                                       44,
                                       0.702,
                                       0.317,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                       'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                       'float64, float64)',
                                       4,
                                       49,
                                       0.217,
                                       0.098,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                       'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                       'float64)',
                                       5,
                                       50,
                                       0.118,
                                       0.118,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                       'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                       '2d, C), int64, float64)',
                                       4,
                                       49,
                                       0.168,
                                       0.168,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                       'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, '
                                       'C), array(float64, 2d, C), float64, float64, float64, float64)',
                                       3,
                                       44,
                                       0.203,
                                       0.203,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                       'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, '
                                       '2d, C))',
                                       3,
                                       44,
                                       0.502,
                                       0.502,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                       'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       2,
                                       31,
                                       6.002,
                                       1.138,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       3,
                                       55,
                                       4.742,
                                       4.742,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       55,
                                       0.122,
                                       0.122,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                       'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, '
                                       'C), array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       1.133,
                                       0.636,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                       'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, '
                                       'int64)',
                                       3,
                                       58,
                                       0.058,
                                       0.058,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                       'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, '
                                       'int64)',
                                       3,
                                       58,
                                       0.061,
                                       0.061,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                       'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       58,
                                       0.129,
                                       0.129,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                       'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                       3,
                                       58,
                                       0.078,
                                       0.078,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                       'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, '
                                       '2d, C), int64, float64, float64, float64, float64)',
                                       3,
                                       58,
                                       0.171,
                                       0.171,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                       'array(bool, 1d, C))',
                                       2,
                                       31,
                                       3.311,
                                       0.95,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3), float64)',
                                       3,
                                       64,
                                       1.832,
                                       1.334,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                       'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       4,
                                       65,
                                       0.499,
                                       0.499,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3))',
                                       3,
                                       64,
                                       0.528,
                                       0.528,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                       'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       31,
                                       0.413,
                                       0.259,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_tip',
                                       'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64)',
                                       3,
                                       68,
                                       0.154,
                                       0.154,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                       2,
                                       31,
                                       1.599,
                                       1.599,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                       'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       31,
                                       3.23,
                                       2.751,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                       'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), '
                                       'float64, float64, float64)',
                                       3,
                                       71,
                                       0.137,
                                       0.137,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._wrap',
                                       'bench_myriapoda.kinematics.legs._wrap(float64)',
                                       3,
                                       71,
                                       0.064,
                                       0.064,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._ik_solve',
                                       'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                       'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                       3,
                                       71,
                                       0.278,
                                       0.278,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, '
                                       '1d, C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                       2,
                                       31,
                                       1.749,
                                       1.749,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                       'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                       2,
                                       30,
                                       1.462,
                                       0.674,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                       'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                       '2d, C), array(float64, 1d, C))',
                                       3,
                                       76,
                                       0.788,
                                       0.788,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.advance_chain',
                                       'bench_myriapoda.bodies.rigid_chain.advance_chain(SpringLinks(array(float64, '
                                       '2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), array(int64, '
                                       '1d, C), array(int64, 1d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                       'Attachment(array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C)), '
                                       'Boxes(array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(bool, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C)), World(array(float64, 1d, C), '
                                       'int64, array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, '
                                       '1d, C)), Coupling(array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(int64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C)), array(float64, 1d, C), int64)',
                                       2,
                                       30,
                                       36.484,
                                       19.222,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.massspring.kernels.spring_forces',
                                       'bench_myriapoda.bodies.massspring.kernels.spring_forces(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                       4,
                                       78,
                                       0.377,
                                       0.377,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                       'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                       'array(float64, 2d, C))',
                                       4,
                                       78,
                                       0.195,
                                       0.195,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                       'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64, float64)',
                                       4,
                                       78,
                                       0.581,
                                       0.581,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                       'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       4,
                                       78,
                                       0.771,
                                       0.771,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.rigid_segments_step',
                                       'bench_myriapoda.bodies.rigid_chain.rigid_segments_step(Attachment(array(int64, '
                                       '1d, C), array(int64, 1d, C), array(float64, 2d, C)), array(float64, 2d, C), '
                                       'array(float64, 2d, C), Boxes(array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C)), '
                                       'World(array(float64, 1d, C), int64, array(float64, 1d, C), int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C)), Coupling(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(int64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                       'array(float64, 1d, C))',
                                       3,
                                       78,
                                       15.338,
                                       4.094,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                       'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       4,
                                       83,
                                       0.419,
                                       0.31,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._cross',
                                       'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, '
                                       'float64, float64, float64)',
                                       5,
                                       84,
                                       0.108,
                                       0.108,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._step_body',
                                       'bench_myriapoda.bodies.rigid_kernels._step_body(int64, Tuple(array(float64, '
                                       '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C)), '
                                       'float64, array(float64, 1d, C), int64, array(float64, 1d, C), Tuple(float64, '
                                       'float64, float64, int64, float64, int64, float64, float64), '
                                       'Tuple(array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C)), array(float64, 1d, C))',
                                       4,
                                       83,
                                       10.825,
                                       8.474,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, '
                                       '2d, C), float64, float64, float64, array(float64, 2d, C))',
                                       5,
                                       86,
                                       0.204,
                                       0.204,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                       'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.185,
                                       0.185,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                       'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                       '2d, C), float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       5,
                                       86,
                                       0.174,
                                       0.174,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64)',
                                       5,
                                       86,
                                       0.456,
                                       0.456,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64)',
                                       5,
                                       86,
                                       0.303,
                                       0.303,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                       'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.646,
                                       0.316,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                       'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       6,
                                       92,
                                       0.331,
                                       0.234,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                       'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, '
                                       'float64, float64, float64, float64, float64)',
                                       7,
                                       93,
                                       0.097,
                                       0.097,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                       'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.174,
                                       0.174,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                       'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.208,
                                       0.208,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.finish_chunk',
                                       'bench_myriapoda.controllers.myriapod.compiled.finish_chunk(array(float64, '
                                       '1d, C), array(int64, 1d, C), Tuple(array(int64, 1d, C), array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                       'C), array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), array(bool, 1d, C), '
                                       'array(int64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C)))',
                                       1,
                                       30,
                                       1.266,
                                       0.753,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, '
                                       '1d, C), float64, array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       2,
                                       97,
                                       0.513,
                                       0.513,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.energy',
                                       'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.612,
                                       0.613,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                       'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                       'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       0,
                                       None,
                                       0.92,
                                       0.92,
                                       False,
                                       True)]},
 'massspring-legless-dry': {'args': 'eNqVVN2L00AQt71+eCCKVyKn50OpesRQCn7ga+68Ikg4H+T6cnKUJF27OdpNSTdIHwSfWoV9kdvj8EH9V53ZTdKv9NQOTTczszO/+c1Mv5Quryo31OdMmqa4z+Kh57b8MCItPhmRccv1xjxyfS5FrYuabkT8kIEu9nkYyQspqn44mkSkL8XtdePuWsCx7w7caAz33jJO+kS53fTiYMADBupK6J0TyHch383kZ2mKEnOHRIpywPirl+ga8E9Bj1PpHIjKOOgz0pNfRbnrhz0inQfxTL6XdItWcopho4k6QLTDKHInkITeStKUe2hSN2lVlN8MQpcv2OkdUf2IOsBA7zoHtOY8VKkAXy8YSqcgKgN3EsbAVOFIpqgNF/OYyc1m/VmvWT96KlO4x9+LGm8DhUMag1rpiz7NQHmdCo9GzguIkSrmqsSgTY18WQ2zdOeacNqUHBsb8S1YkOvdjOE9UD9yivQxfUL315h7rpmj5rHMOLOS9HlxtjbEeZHFudRxEIidBLP1iw0vbRBDYbfUs60Ez7b+Qjds2p5K9Jgud26lZuMvDWwnJVRF9XUYDojLlgev5IFWwsTt6MIRBPpvL/hUYr0fajZ3voHzPe2s8SuB9G1qT5OMFj2lpxprKqs8GsBjIeGxpnlUWbI5BhZ/FNM8BgYEUXHE3tr2wV8DdwNGcPnLJ/FoQJb2T2+mSTvLsyjKfhgzLp0qAEKAvtjusCBkJ7iuCzxRvAntAKjK/gFZayZ9P0OoPxOo++JQpTeVRz0bjf84qNJ/FbN+LPLoqZlEJhoAqbNpxYz5LvyDad47G0J6iVjpQKphhBbMpLJbs2yO83pazO3pfMN+zwvTgDAU5sPfNj5VPgUntwDtrctYBdBZGKodDUD3YT5TV+lmktYfg3g6+A==',
                            'case': 'worm/massspring/flat',
                            'events': [('bench_myriapoda.world.terrain_kernels.signed_distance',
                                        'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        0,
                                        None,
                                        9.013,
                                        0.564,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_phi',
                                        'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        1,
                                        0,
                                        5.216,
                                        0.293,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                        'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                        'float64, float64)',
                                        2,
                                        1,
                                        0.188,
                                        0.188,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                        'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        2,
                                        1,
                                        0.354,
                                        0.109,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                        'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                        'C), float64, float64)',
                                        3,
                                        3,
                                        0.244,
                                        0.245,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                        'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        2,
                                        1,
                                        4.382,
                                        0.279,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                        'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        3,
                                        5,
                                        4.103,
                                        0.661,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                        'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, int64)',
                                        4,
                                        6,
                                        3.441,
                                        0.952,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._candidate',
                                        'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        0.685,
                                        0.403,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                        'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                        'float64, float64, float64, float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        6,
                                        8,
                                        0.282,
                                        0.282,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._descend',
                                        'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, float64, float64, float64, '
                                        'int64, int64)',
                                        5,
                                        7,
                                        0.56,
                                        0.56,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                        'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        0.866,
                                        0.866,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                        'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                        'int64, int64, int64)',
                                        5,
                                        7,
                                        0.377,
                                        0.377,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                        'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                        'float64, float64, float64, float64)',
                                        1,
                                        0,
                                        3.233,
                                        2.705,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        2,
                                        13,
                                        0.234,
                                        0.234,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                        '1d, C), float64, float64, float64, float64)',
                                        2,
                                        13,
                                        0.294,
                                        0.294,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                        'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, '
                                        'C), float64, array(float64, 1d, C), float64, float64, int64, array(float64, '
                                        '3d, C))',
                                        0,
                                        None,
                                        0.286,
                                        0.117,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                        'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, '
                                        '2d, C), float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                        1,
                                        16,
                                        0.169,
                                        0.169,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.advance',
                                        'bench_myriapoda.bodies.massspring.kernels.advance(array(float64, 2d, C), '
                                        'array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                        'array(float64, 3d, C), int64, array(float64, 1d, C), int64, array(float64, '
                                        '1d, C), array(float64, 1d, C), int64, array(float64, 3d, C), array(float64, '
                                        '3d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, 1d, '
                                        'C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                        'array(float64, 1d, C))',
                                        0,
                                        None,
                                        37.638,
                                        10.907,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._corner_major',
                                        'bench_myriapoda.bodies.massspring.kernels._corner_major(array(float64, 2d, '
                                        'C), array(float64, 3d, C))',
                                        1,
                                        18,
                                        0.147,
                                        0.147,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._flat_ground',
                                        'bench_myriapoda.bodies.massspring.kernels._flat_ground(int64, '
                                        'array(float64, 1d, C))',
                                        1,
                                        18,
                                        6.889,
                                        0.948,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                        'array(float64, 1d, C), float64, float64, float64)',
                                        2,
                                        20,
                                        5.941,
                                        5.128,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                        'C), int64, float64, float64, float64)',
                                        3,
                                        21,
                                        0.305,
                                        0.305,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_normal',
                                        'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        3,
                                        21,
                                        0.508,
                                        0.276,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                        'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                        'float64, float64)',
                                        4,
                                        23,
                                        0.127,
                                        0.127,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                        'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        4,
                                        23,
                                        0.105,
                                        0.105,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._column_forces_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._column_forces_flat(array(float64, '
                                        '3d, C), int64, bool, array(float64, 1d, C), array(float64, 1d, C), uint64, '
                                        'int64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C))',
                                        1,
                                        18,
                                        8.652,
                                        8.652,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_vectors_c',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_vectors_c(array(float64, '
                                        '3d, C), array(float64, 2d, C))',
                                        1,
                                        18,
                                        0.489,
                                        0.489,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_rows',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_rows(array(float64, 3d, C), '
                                        'int64, array(float64, 1d, C), uint64, uint64)',
                                        1,
                                        18,
                                        0.478,
                                        0.478,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._node_rows',
                                        'bench_myriapoda.bodies.massspring.kernels._node_rows(array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(int64, 1d, C), int64, int64, uint64, uint64, '
                                        'uint64, array(float64, 1d, C), Tuple(bool, float64, float64, float64, '
                                        'float64, float64, float64), array(float64, 1d, C), array(float64, 1d, C))',
                                        1,
                                        18,
                                        8.08,
                                        4.645,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._positions_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._positions_flat(array(float64, '
                                        '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                        'C), array(int64, 1d, C), float64, int64, uint64, uint64, float64, bool, '
                                        'bool, float64, float64, float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        2,
                                        29,
                                        3.434,
                                        3.434,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                        'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64, float64, float64)',
                                        1,
                                        18,
                                        0.791,
                                        0.791,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                        'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        1,
                                        18,
                                        0.962,
                                        0.962,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._node_major',
                                        'bench_myriapoda.bodies.massspring.kernels._node_major(array(float64, 3d, '
                                        'C), array(float64, 2d, C))',
                                        1,
                                        18,
                                        0.243,
                                        0.243,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_rest_lengths',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_rest_lengths(array(float64, '
                                        '2d, C), bool, array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                        'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C))',
                                        0,
                                        None,
                                        0.539,
                                        0.294,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.fibre_stretch',
                                        'bench_myriapoda.bodies.massspring.kernels.fibre_stretch(array(float64, 2d, '
                                        'C), int64, int64)',
                                        1,
                                        34,
                                        0.096,
                                        0.096,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.face_scales',
                                        'bench_myriapoda.bodies.massspring.kernels.face_scales(array(float64, 2d, '
                                        'C), bool, array(float64, 1d, C))',
                                        1,
                                        34,
                                        0.149,
                                        0.149,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_energy',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_energy(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), float64)',
                                        0,
                                        None,
                                        0.314,
                                        0.314,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                        'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C))',
                                        0,
                                        None,
                                        3.294,
                                        0.728,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                        'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                        'array(float64, 2d, C))',
                                        1,
                                        38,
                                        2.565,
                                        0.476,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                        'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                        'float64, float64, float64, float64, float64, float64)',
                                        2,
                                        39,
                                        2.09,
                                        2.09,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                        'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, '
                                        'C), array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), '
                                        'float64, array(bool, 1d, C))',
                                        0,
                                        None,
                                        1.138,
                                        1.138,
                                        False,
                                        True)]}}
