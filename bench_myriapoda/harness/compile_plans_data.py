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
 'fem-legless-dry': {'args': 'eNqtVs1rE0EUT9puaqmotFZrWiXsQVJZEq1ByM1YUCTEg7Qo1RA2m7Gzku6GzSySg+Cp0TDgoaMerDe/9Y/xT3K+djOb3aQfNAth5s283/u9N+/NmzczH97Pp/ivTvJ5fMXxd5tmwXI9UEC9DugWzGYXeaaFCF5sMEnDA5brUJlvIdcj+wTPWm6n54Edgs/FF+OATqfHBwRrFc8ze2zXmaZvt5HtUGHGbb4E1Nw+edQnr0keay22ncBpmMHLMbSuZbZNj4Hdb7smU4NnpeKMY+4CSu8FW7hTYlZs9MpuIUiqd7HWsNwWINVVv08eE7q5Ze+S6hTOtM2e61N30xskgFgyGdG8BDJy6y0jt7FGAozaxykOwijCucA+PM/nF/DsQweBHeAp3OAS1myHkYKXKZdM195xQIu8hcvVrIBaqU7BVXgVXsOLwjjfHpqGudrXMUazVHda6o4Svx1qf5qgnR6jfSvU3hfaiKoUYZl9bFgSQ6ijOK6h4EY9GqJ+kZwqsNynSgaFyrIPRSdixHZMErGhkTChnxEIhiK5IJayyd8oTERnApxYksPsWH7Kik4HZQlRUgW6mOi8GFZixUBrD5m2A3g9bPqdNlDrQRNlx2wVw7OqiMPDmuX6DiLVObXe4Bae23Js19lkEiV9txlIiSoXUVgk23zns8ScMRLz0EjIAyMh2+vDSvsmU8TC/7h/+WRzuQSUQDhKIjcR4njiqCvHgqAVAGrfpXslHv0narwr/CuLf5rxz6uzsM63NYbb2Poei87Nww8jwrXOrP8Ig3ugBjfRqaMLjxOqowDwQP1Urq9YmHiQeIg0GqIu9adzMn9OTJ1z/CU5GrzSy/w/xrfEy1mWtHJjiqO9rjSMjD/sGPDGO9oqLkVaVzpsXfSStfBFQcsfuWVB7bekNQgs80jNJySTTtkN+iwfHiSm0/rhte3Hs+xPkGVPU+lUKrGKx1Tm+umL/cSz9Cdnwyny4CfyV0ZEj7bRimim9NqX74h7rtsGphN9R8w0qZTQbFgIrg7ZJIphZg3YWSMiZH3ZQXSxz1An2Umt7+jCgcgtQUN4ELm9xJIy1PkkZBTphcbYlm4c0v8VoFGGCUtBZy0Hw7BHqtOwAUvCon55bPW90BMBP/oEOlCeQAsiG9jZqS+gz8G7ChT+A+oYwrM=',
                     'case': 'worm/fem/flat',
                     'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                 'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.509,
                                 0.509,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                 'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.168,
                                 0.168,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                 'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 0.332,
                                 0.332,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.239,
                                 0.239,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                 'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                 'C), float64, float64, float64)',
                                 0,
                                 None,
                                 12.305,
                                 0.53,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_phi',
                                 'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 1,
                                 4,
                                 6.711,
                                 0.48,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                 'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                 'float64)',
                                 2,
                                 5,
                                 0.196,
                                 0.196,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                 'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 2,
                                 5,
                                 0.336,
                                 0.126,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                 'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                 'float64, float64)',
                                 3,
                                 7,
                                 0.21,
                                 0.21,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                 'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 5,
                                 5.699,
                                 0.451,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                 'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 3,
                                 9,
                                 5.249,
                                 1.193,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                 'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, int64)',
                                 4,
                                 10,
                                 4.055,
                                 1.418,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._candidate',
                                 'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 0.777,
                                 0.445,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                 'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 6,
                                 12,
                                 0.332,
                                 0.332,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._descend',
                                 'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                 5,
                                 11,
                                 0.468,
                                 0.468,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                 'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 0.922,
                                 0.922,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                 'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                 'int64, int64)',
                                 5,
                                 11,
                                 0.471,
                                 0.471,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                 'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 1,
                                 4,
                                 5.064,
                                 4.451,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 2,
                                 17,
                                 0.27,
                                 0.27,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 2,
                                 17,
                                 0.344,
                                 0.344,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                 'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, float64, int64, array(float64, 3d, C))',
                                 0,
                                 None,
                                 0.369,
                                 0.147,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                 'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                 1,
                                 20,
                                 0.222,
                                 0.222,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.advance',
                                 'bench_myriapoda.bodies.fem.body_kernels.advance(array(float64, 2d, C), '
                                 'array(float64, 2d, C), Tuple(array(float64, 1d, C), array(int64, 2d, C), '
                                 'array(float64, 3d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                 'array(float64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, '
                                 '1d, C)), array(float64, 3d, C), Tuple(array(int64, 1d, C), array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                 'C), array(float64, 1d, C)), Tuple(array(int64, 1d, C), array(int64, 1d, C), '
                                 'array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C)), int64, '
                                 'array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, 1d, C), int64, '
                                 'Tuple(array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, '
                                 '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C)), array(float64, 2d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 26.913,
                                 5.436,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                 'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                 'float64, bool, array(float64, 3d, C), array(float64, 2d, C))',
                                 1,
                                 22,
                                 0.317,
                                 0.317,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 22,
                                 10.36,
                                 0.474,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                 'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 0.39,
                                 0.39,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 5.199,
                                 5.199,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 3.839,
                                 1.915,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                 'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 3,
                                 27,
                                 1.925,
                                 0.754,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                 'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                 'float64, float64, float64, float64, float64)',
                                 4,
                                 28,
                                 0.97,
                                 0.97,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                 'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64)',
                                 4,
                                 28,
                                 0.2,
                                 0.2,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                 'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), '
                                 'array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 24,
                                 0.459,
                                 0.459,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                 'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                 'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                 'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 1,
                                 22,
                                 2.166,
                                 0.479,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 2,
                                 32,
                                 1.687,
                                 1.687,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.segment_spines',
                                 'bench_myriapoda.bodies.fem.body_kernels.segment_spines(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C))',
                                 1,
                                 22,
                                 0.849,
                                 0.849,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                 'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 1,
                                 22,
                                 0.556,
                                 0.556,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                 'array(float64, 1d, C), float64, float64, float64)',
                                 1,
                                 22,
                                 6.112,
                                 4.79,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                 'int64, float64, float64, float64)',
                                 2,
                                 36,
                                 0.596,
                                 0.596,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_normal',
                                 'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 36,
                                 0.726,
                                 0.436,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                 'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                 'float64)',
                                 3,
                                 38,
                                 0.17,
                                 0.17,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                 'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 3,
                                 38,
                                 0.12,
                                 0.12,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                 'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                 'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64, float64)',
                                 1,
                                 22,
                                 0.483,
                                 0.483,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                 'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                 '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                 1,
                                 22,
                                 0.635,
                                 0.635,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity',
                                 'bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 1d, C), float64)',
                                 0,
                                 None,
                                 0.216,
                                 0.216,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.559,
                                 0.559,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                 'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '2d, C))',
                                 0,
                                 None,
                                 0.496,
                                 0.496,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                 'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 0.857,
                                 0.506,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                 'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 46,
                                 0.352,
                                 0.352,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                 'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), float64, '
                                 'array(bool, 1d, C))',
                                 0,
                                 None,
                                 0.626,
                                 0.626,
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
 'hybrid-legless-dry': {'args': 'eNrtWU1sG0UUjhPb+SGUqj9Q3BaFlUABrVKaWki+4RZCKzc9VEUtaqvtenfsmWa9686uk/gQiVMC0t66wAGBVIkTEv//lJ/CgUOP3JE4VUJcuXAqb352vbbXzo9DUaBZZf32zcybNzPvfe/NzCvp1w8/PsT/LgfT0/6jdqNW1mcMh6IZr1lH7oxedj2qG17g79UYR6PIcGzgNQzPocH1wB81nHqTomrg7+ou7BZo15ucCPxMkVK9yWqNlRvE8ogNzKxTvoqgu+vBmbVgJZj2MyarHuARnPUPdElzDd3SKRM2Zzk6a4YnZcO0rdcQqFdhBc/mWS/EWyKmh4PSc35GMxwTBaVDjbXgbACVTVILSsN+1tKbTgOGmzoRhCL260zRaSlInZo11akTTwWhjPk3hrkQpiIeD/vHD/Hv3f7oKdtDVURjuuH9fobYTCn8COiSdUnVRmbwKj5QyglRB0vD+BA+jB/z94rOefWoazw1/26PTnPQdkS27VT8WNT6zT6tUz1aH41aXxetPWhyBBfYw8i8ILHidctVY3LbR9SS+rbUqYgLawGTg5U1aKwCmWOP1/4hKFajH4uRasIHPGrIaLFkgSjKJT+dYtra9BEniiSZ66lfrKQIjxI9efkLc82+VmMaKqw2c5CDXQ4C/ujpxEbcR8416haK+0hGuOI0F6zCYrJO2Nq9HK3dpdbCFvk7D86RMZyG7QWlsbh74vP++Es2cexzjBOz9kusFS6uRQ41x6tdTLQvNdFm1QSbudzywPel6VT9m3yM08lCppJ73BK7TZUBJQv1wAnI/AdyJAW52m2O1DbbT8bQJNtowQl++jXAkYfbcC0V4Ro+HC7CPqFEo90Poyl9Tyqyws2wyJc//la4n18p5bDO1THiFmNz/WHNwaRWmM3j6oUXU0NDYt138BKpG7LZ2U1aspqA8WrS8qj86zIzlA9Dk7/w6/DQUOKUziYPJWRLyUl9T21sccLaO3lBN1h9dgB2I1HvZO6AzM1M3L8vYGPTyHHxo1jCEgtOIkauMSAa6QYiwKDiKosKzyQGnNk+oQW6/DgKKnNxA9/CVMTG8UnyOKajMF/ohv1WKnnccSyk2+2pZLoM3AAwf0+YO4aZ1h6hByuPJ1pvSR3yEYg/kATiNwSIM/D2L8YnMC5vcEDkc/1pNNd3twJlA7EH8fi2qdgkavY2ks96GUmBJ8CqyLhh3bIJNg/l3OaVfklWK458Hs28kzjzR5OixSZLE9l8pF/0d4dClPcW4TfPM1FFbjGulHYnWa1MPLjVXtpEnjm76ewT1P8yCsJuamtB+J8w0WMDdNkfyI5tB/vo9g2d29BXUcqsyn0Q7EQmzkCSa3ZueELLCrc6dpRnr6yf6PrZCkGWCdslP7Uc+KnFwM/aWoUiSKbTHvLY6cXzNY3YUJA2HFSB71rDNSxWXtNdKE9f05ZYtTltyaELQJyUxCixDa3uUUk5FWicriNaC/xxd6GpVQh1Yd81ymheLcOo0yChUhcMRhgQBzixqDOiXpFFQIgiIHjRuA05vmYRm+lQCZUpCwL62UVs19NtA2mGxRV/ooxsA2u1JiV63TH1mbJjEthe4maZEnNmAVEbWVBvbO6F+dMg1mWTXr3wG6SmIed+dno/O/2vZqdfx8LYzz2y09t+pkKWkQlOonueBg7UBEdkpOUY4JRQ7Y6v9PAzSqrE1AysEzvwJ4qepxu4hmx+4Fn1Sy3GtiSp3yQPpzNJvdGWQd4GWDQAFq8F/vAioE5qKcC/+JPs7MkjuhzvJNatioaWPVAV4GJ8AYprukeg4YOkVm9YLkAODAUgM1NxqAG/Wc+h1xoIYAnfwX/6mePOMhLw4t/l9P87V7zZa626c0VYodEq1ReJxyzPQ5RqMP8mj14UVmyiQomh1SA0QIhIsw8WhHDTjeb+vEMtU8y9w+l7my1+298u18sWYfyZigYeB8a1LH6zy1qdcp+kyCVmgwXHjFsHqwQrPlsGKz4LxKklmC/DgRhHITQH/ojF3HBEt6swQdCwDnUWbPZiIj2dVpHHaum1cObGTjgQhQg04HFxEbLFkHM/YbzXCeN37Qlj+/G2gnP4HWZG/Jj9iLiDkLgnbiBiH7l+lwQbZyqy3/YEVAnvAApSGWU1fgPSdSHScZWgrnMvEhPUqU9CEWP/xXS4Ogm2e/Uge+XhJa5+YvcUHYMU4tY57VDkOcOV0kTihhZK1xjmnNym/Rzfu30fbXz/2FFHDltkx+4YfpAjz8n40LU64b2V+M/xlRlLWJmcPGrYJ9Yl7Kt1uHArmuNTYo4jdboJCSQ9vyXBR/Bjv2ODJPBndnUL1Ph960u9A4HupxDoBMjELguVCBpyITTkohr9IasPivUub0HBRuEyxoprqfCdeyEcRQtFItaRENDFpyrR7Ea8QR5yV/bOydvUwqosLERQJpIJLgbN/A00NaHE',
                        'case': 'chain/hybrid/fig4-drop',
                        'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                    'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.709,
                                    0.709,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                    'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.158,
                                    0.158,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                    'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.27,
                                    0.27,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.229,
                                    0.229,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.253,
                                    0.253,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                    'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    0,
                                    None,
                                    10.153,
                                    0.467,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_phi',
                                    'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    1,
                                    5,
                                    5.311,
                                    0.46,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                    'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                    'float64)',
                                    2,
                                    6,
                                    0.201,
                                    0.2,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                    'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                    'float64, float64)',
                                    2,
                                    6,
                                    0.316,
                                    0.124,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                    'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                    'float64, float64)',
                                    3,
                                    8,
                                    0.193,
                                    0.193,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                    'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    2,
                                    6,
                                    4.334,
                                    0.366,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                    'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                    'float64, float64, float64)',
                                    3,
                                    10,
                                    3.968,
                                    0.849,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                    'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, int64)',
                                    4,
                                    11,
                                    3.12,
                                    1.007,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._candidate',
                                    'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    0.701,
                                    0.41,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                    'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    6,
                                    13,
                                    0.291,
                                    0.291,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._descend',
                                    'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                    5,
                                    12,
                                    0.502,
                                    0.502,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                    'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    0.596,
                                    0.596,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                    'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                    'int64, int64, int64)',
                                    5,
                                    12,
                                    0.313,
                                    0.313,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                    'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                    'float64, float64, float64, float64)',
                                    1,
                                    5,
                                    4.375,
                                    3.764,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    2,
                                    18,
                                    0.274,
                                    0.274,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                    'C), float64, float64, float64, float64)',
                                    2,
                                    18,
                                    0.338,
                                    0.338,
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
                                    0.773,
                                    0.474,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                    'array(float64, 3d, C))',
                                    1,
                                    21,
                                    0.299,
                                    0.114,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                    'float64, float64, array(float64, 2d, C))',
                                    2,
                                    22,
                                    0.185,
                                    0.185,
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
                                    52.923,
                                    2.933,
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
                                    49.99,
                                    20.291,
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
                                    0.344,
                                    0.344,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                    'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    0.236,
                                    0.236,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    3.381,
                                    3.381,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    3.921,
                                    1.262,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                    'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    4,
                                    29,
                                    2.659,
                                    0.788,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                    'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    5,
                                    30,
                                    1.533,
                                    1.533,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                    'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    5,
                                    30,
                                    0.339,
                                    0.339,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                    'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, '
                                    'C), array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    3,
                                    25,
                                    2.268,
                                    0.459,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    4,
                                    33,
                                    1.809,
                                    1.81,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                    'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                    'array(float64, 2d, C))',
                                    3,
                                    25,
                                    0.179,
                                    0.179,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                    'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, '
                                    'C), float64, float64, float64, float64)',
                                    3,
                                    25,
                                    0.464,
                                    0.464,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                    'array(float64, 1d, C), float64, float64, float64)',
                                    3,
                                    25,
                                    4.383,
                                    3.325,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    4,
                                    37,
                                    0.324,
                                    0.324,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_normal',
                                    'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    4,
                                    37,
                                    0.734,
                                    0.315,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                    'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                    'float64, float64)',
                                    5,
                                    39,
                                    0.256,
                                    0.256,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                    'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    5,
                                    39,
                                    0.163,
                                    0.163,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                    'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                    '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    25,
                                    0.451,
                                    0.451,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                    'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                    'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    25,
                                    0.578,
                                    0.578,
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
                                    13.495,
                                    4.505,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                    'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    44,
                                    0.417,
                                    0.332,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._cross',
                                    'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                    'float64, float64)',
                                    4,
                                    45,
                                    0.085,
                                    0.085,
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
                                    3,
                                    44,
                                    8.573,
                                    5.883,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                    'C), float64, float64, float64, array(float64, 2d, C))',
                                    4,
                                    47,
                                    0.155,
                                    0.155,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.matvec',
                                    'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    4,
                                    47,
                                    0.144,
                                    0.144,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                    'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                    4,
                                    47,
                                    0.117,
                                    0.117,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                    'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                    '2d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    4,
                                    47,
                                    0.111,
                                    0.111,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    4,
                                    47,
                                    0.318,
                                    0.318,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    4,
                                    47,
                                    0.172,
                                    0.172,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                    'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    4,
                                    47,
                                    0.133,
                                    0.133,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                    'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    4,
                                    47,
                                    1.27,
                                    0.897,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                    'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    5,
                                    55,
                                    0.373,
                                    0.268,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                    'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                    'float64, float64, float64, float64)',
                                    6,
                                    56,
                                    0.105,
                                    0.105,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                    'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                    'float64)',
                                    4,
                                    47,
                                    0.125,
                                    0.125,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                    'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                    4,
                                    47,
                                    0.144,
                                    0.144,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                    'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.448,
                                    0.448,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.energy',
                                    'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.412,
                                    0.411,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                    'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.421,
                                    0.421,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                    'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                    'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                    0,
                                    None,
                                    0.568,
                                    0.568,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                    'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.94,
                                    0.455,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                    'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                    '2d, C), array(float64, 1d, C))',
                                    1,
                                    64,
                                    0.485,
                                    0.485,
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
                                    0.666,
                                    0.666,
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
 'massspring-legless-dry': {'args': 'eNqtVN1rE0EQt2mTtCCKDSfV+hCilvMIgaqIb2ntoZazRaQ+SSmXy9o9Se7CZQ/Jg6IvicK+df1CfPAD/05ndvfu8nGtimbhsjszO/Obmd/Oq4V31uIp+dsXpskvBHG35Ta8MCINNuiRfsNt9VnkekzwygFKDiLihQHIYo+FkTgSvOyFvUFEDgU/M6tcmXHY99yOG/Xh3nbAyCGRZout2O8wPwBxKWw9IxDvSOyOxAth8oXA7RLBi37Abt1EU58999uMCmeDl/r+YUDa4g0vHnhhmwjnYjwSjwSdp6WcZILeQG7A22YUuQMIQk/rMMU2quRNWubFu53QZWN6epaXn6IMMNBzzgatOJdkKMDX9rvCmeOljjsIY6jU3JZIUBsuxjH1zXp1vV2vbl0TCdydo4LCW8PFIIxBreSgdiMQniTCrZFzgGUkgkykFUpVy1/TbibunOBOqfS2diy+MQ3WeiWt8CqILzsFeoVepWszlbuuKkfNnfdpzSwdPs/P/DF+bqR+Pig/CKSpnTXVoQkHG5YhsVvyi4xanWEU0J25fkCQ0MW9uNchE5xSbDOlM1s6sjAGL3phHDDhlAEsgr/Hlx4HfhjsIQXHSPcA7ak9EpDIfWnxJJdQ9dxi1XNT38fcP+oarvGfErWZa1qv/pN4/X+IVSqyYZ80aGgPw689FNie4eSzmSKc8ZvXY2v+lHn5Thh2iBtMvvqFFkgFPPdlFRxbiPZLYzalWA0nORiW34LxeWVs6J5bErFNm0Md0aJd2lVYkzVNYgNIPKdJXFFFkVHSIQIV+VJI4hjoEJbys50xyKR08nHT3ZR2D8eIBlZD5ENF0QyzrusmSMZ8TRmzqRgjLappn/5iI6F/K6T1HK9DLB80ZvJ6NpNalovMowR5vAREtxWiNM6fQpNAvmdjwMjG0/RAzFFlHW0Crlgv/cg1RaExIyH11igdLXmdLuR2Oht6P7JyKUDoCuPhv41fGU/CyU1AWas0pgHQMaotKwCqhBnTPidVIo1f2VC9bA==',
                            'case': 'worm/massspring/flat',
                            'events': [('bench_myriapoda.world.terrain_kernels.signed_distance',
                                        'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        0,
                                        None,
                                        11.223,
                                        0.728,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_phi',
                                        'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        1,
                                        0,
                                        6.461,
                                        0.312,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                        'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                        'float64, float64)',
                                        2,
                                        1,
                                        0.294,
                                        0.295,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                        'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        2,
                                        1,
                                        0.477,
                                        0.169,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                        'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                        'C), float64, float64)',
                                        3,
                                        3,
                                        0.309,
                                        0.308,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                        'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        2,
                                        1,
                                        5.378,
                                        0.325,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                        'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        3,
                                        5,
                                        5.053,
                                        0.861,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                        'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, int64)',
                                        4,
                                        6,
                                        4.193,
                                        1.197,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._candidate',
                                        'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        1.13,
                                        0.623,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                        'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                        'float64, float64, float64, float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        6,
                                        8,
                                        0.508,
                                        0.508,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._descend',
                                        'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, float64, float64, float64, '
                                        'int64, int64)',
                                        5,
                                        7,
                                        0.752,
                                        0.752,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                        'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        0.61,
                                        0.61,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                        'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                        'int64, int64, int64)',
                                        5,
                                        7,
                                        0.504,
                                        0.504,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                        'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                        'float64, float64, float64, float64)',
                                        1,
                                        0,
                                        4.033,
                                        3.314,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        2,
                                        13,
                                        0.32,
                                        0.32,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                        '1d, C), float64, float64, float64, float64)',
                                        2,
                                        13,
                                        0.399,
                                        0.399,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                        'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, '
                                        'C), float64, array(float64, 1d, C), float64, float64, int64, array(float64, '
                                        '3d, C))',
                                        0,
                                        None,
                                        0.35,
                                        0.13,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                        'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, '
                                        '2d, C), float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                        1,
                                        16,
                                        0.22,
                                        0.22,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.advance',
                                        'bench_myriapoda.bodies.massspring.kernels.advance(array(float64, 2d, C), '
                                        'array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                        'array(float64, 3d, C), int64, array(float64, 1d, C), int64, array(float64, '
                                        '1d, C), array(float64, 1d, C), int64, Tuple(array(float64, 3d, C), '
                                        'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C)), '
                                        'array(float64, 2d, C), array(float64, 1d, C))',
                                        0,
                                        None,
                                        25.496,
                                        7.534,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._corner_major',
                                        'bench_myriapoda.bodies.massspring.kernels._corner_major(array(float64, 2d, '
                                        'C), array(float64, 3d, C))',
                                        1,
                                        18,
                                        0.145,
                                        0.145,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._flat_ground',
                                        'bench_myriapoda.bodies.massspring.kernels._flat_ground(int64, '
                                        'array(float64, 1d, C))',
                                        1,
                                        18,
                                        7.739,
                                        0.624,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                        'array(float64, 1d, C), float64, float64, float64)',
                                        2,
                                        20,
                                        7.115,
                                        5.831,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                        'C), int64, float64, float64, float64)',
                                        3,
                                        21,
                                        0.398,
                                        0.398,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_normal',
                                        'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        3,
                                        21,
                                        0.885,
                                        0.449,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                        'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                        'float64, float64)',
                                        4,
                                        23,
                                        0.228,
                                        0.228,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                        'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        4,
                                        23,
                                        0.208,
                                        0.208,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._column_forces_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._column_forces_flat(array(float64, '
                                        '3d, C), int64, bool, array(float64, 1d, C), array(float64, 1d, C), uint64, '
                                        'int64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C))',
                                        1,
                                        18,
                                        4.952,
                                        4.952,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_vectors_c',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_vectors_c(array(float64, '
                                        '3d, C), array(float64, 2d, C))',
                                        1,
                                        18,
                                        0.26,
                                        0.26,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_rows',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_rows(array(float64, 3d, C), '
                                        'int64, array(float64, 1d, C), uint64, uint64)',
                                        1,
                                        18,
                                        0.26,
                                        0.26,
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
                                        3.275,
                                        1.917,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._positions_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._positions_flat(array(float64, '
                                        '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                        'C), array(int64, 1d, C), float64, int64, uint64, uint64, Tuple(bool, '
                                        'float64, float64, float64, float64, float64, float64), Tuple(float64, bool, '
                                        'float64, float64, float64, float64))',
                                        2,
                                        29,
                                        1.358,
                                        1.358,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                        'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64, float64, float64)',
                                        1,
                                        18,
                                        0.526,
                                        0.526,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                        'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        1,
                                        18,
                                        0.676,
                                        0.676,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._node_major',
                                        'bench_myriapoda.bodies.massspring.kernels._node_major(array(float64, 3d, '
                                        'C), array(float64, 2d, C))',
                                        1,
                                        18,
                                        0.129,
                                        0.129,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_rest_lengths',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_rest_lengths(array(float64, '
                                        '2d, C), bool, array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                        'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C))',
                                        0,
                                        None,
                                        0.593,
                                        0.326,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.fibre_stretch',
                                        'bench_myriapoda.bodies.massspring.kernels.fibre_stretch(array(float64, 2d, '
                                        'C), int64, int64)',
                                        1,
                                        34,
                                        0.098,
                                        0.098,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.face_scales',
                                        'bench_myriapoda.bodies.massspring.kernels.face_scales(array(float64, 2d, '
                                        'C), bool, array(float64, 1d, C))',
                                        1,
                                        34,
                                        0.169,
                                        0.169,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_energy',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_energy(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), float64)',
                                        0,
                                        None,
                                        0.362,
                                        0.362,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                        'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C))',
                                        0,
                                        None,
                                        2.425,
                                        0.428,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                        'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                        'array(float64, 2d, C))',
                                        1,
                                        38,
                                        1.997,
                                        0.272,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                        'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                        'float64, float64, float64, float64, float64, float64)',
                                        2,
                                        39,
                                        1.725,
                                        1.725,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                        'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, '
                                        'C), array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), '
                                        'float64, array(bool, 1d, C))',
                                        0,
                                        None,
                                        0.676,
                                        0.676,
                                        False,
                                        True)]}}
