"""Compile plans recorded by ``python -m bench_myriapoda.harness.cold_compile --record``: generated, do not edit.


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
 'hybrid-legged-dry': {'args': 'eNrtHFuMG1fV67W9D/IiaWnqlmVlEeSGUdLuGhT/4YaGVN5UVVpEpRCNZsfjveO1Z5zxeLMmqoSQsgvSlZDa4TM/KAUkSJ+8C6UvGigt4lEoDyHxRYX6lR9++Cjn3HvnYXvGu+s4Sx6TUbx37vuec+6555x7znw59Y2FRxLs32knn6d3Gu3GonJINS3tkN1paq1DymLLthTVdug+GXNkS1NNA/Laqm1azpMOnVDNZsfSlhy6q7+wv0Oj2WEJh6ZLlqV0sNbkYluv27oBmRlzsabBcE86D607jzt5mq5gdYeMkwzd39dbS1XqioWdHaubCjYjO0TDlKE0NJheFQs+XcBRdPusXrGJU/4MTcuqWdGc8t3tdeekA5UresMpJ2mmrnTMNix37KjjdnG7ghPNi46k2bmKNHv0Hsft48TFJOsEp0im3PHJbva+h048aNjakmYF5kZup2ndwEmRO2AumZa+ZGgV56tkfznLu7qrnCR3k4+SGbqPD86qe0OT2RNPRQyahbbjom3vxOe91t8a0HosovV9Xutv89Y2NDlMivhgssCTJGf39ysF+u1ekd/rd8ScSqS47mA/JLcOjSVIZvGxu194CmsMysKkFPICj+Rm+FmigBdlw5/ebrraDOiOF4lkNnJ+gZISPDnvKYi/AGt8WwvMMIe1/Ro5hgLpPOsv5/fpo4pnF3kzb7zAEhHQaxyeuXWvQQGeMIpJRVBMwcPtd32KyflT5tDBnX1X384GRmIruqGxzf1ou1nXgps7zXkITqzEpkS8KS3nA2CL2JL3m2ZdU4zuLZlahFwH9uBedw+6FLuXrwvLgwT7PUGwHe/hOOiwCRRDnwKrUfTq83SBqO7WoWnVbBu2U5bEdKt06vOGbhqPIhsMTBjW2WF4wcYlQNkMPc8qnuqfrRS6laVQviaFMg0pFLVSyFY+jaC5JEAz89g744kEQ18+pK40Gz6FUWZ3wWEb8zaa5fywkx8KgvfdytnzV4GBiL6vJWUMPYGNVlYYBTD57BgDfFrscnGukHPljGBaj/tsiqwhk15HXpBOJRKcRcUcIeYIMUe4uTjCQCGjX0R4xhMRFlLdIkLEeD1UHrOQmIXELOQmYyGjwBQTTZ4NGDiqdPohpaFVerVIkE2w+ImgSuUqjq52xnXww0xvQ224rwEfYCcbAGSbvjFQQz5XTtNMVdfqFVBZ6USlYygNXQVVz2xoS4pDU1/SbPiTbLQdOtVQVuWqaakaaMt0l260bMVQNVmtKy1QhQ8saoZK5EbH0pWmWVEOLZoVHdRl0afMazt0xyMs8bBiKY0WzmeG3hnMcoE2uzr7KQaw5zxZLsdtL8zWUgwYHc6Vd5ILeZpp8j5pqsFmtAOVdFtXZJhJx6ETS5ayotuQSvNV0IxtWmfakJiyNcuSl3WjAo0x7dBxRQU4jGHKsBqQqkK7Vl2v4OrJRfKUuxBmK+QLeeyTY4lEMDcfubCtkd9V1nazBSsdwX4Yyd5m2H3etb8AFj+MWBxDsJ8BmlsB2I+dBeQAXrSGYiNdpgiQKmSvwv8VRKS+qsH7pGLbAstTmKybqlJ36HRdN5Zlw6ygUTd1soWm4OTJRUifsRtNSFeAkDOCMBGr9OMRRKzCAnStAmOsYl87jvL3+9krQ/3Xk4lEMDd//Rz1W+s19LzdyiHcZRC+ysPJHdDLiHfXpncX214vBE4b0ns6kN7zRWLnSa6/0LWgl7ipkO3WyRCNGs2ITKOmx4IWvw3Me/OD5fHvu/I4fTFUGJ8fvSw1mN6HEccYNn4QOMqijMCfCBh+M23/MoYc/BrZX/5IrwX4Nj5au+/S4odirCtMUigx5AV/uS3+XDnbj8Y8eU/Yb0tAEFfwagA43OfGwmwkNxgWRmZv7p5bGOcLQ4zE3hhV/8jTMv+RjNAyt8JwhuK6cyEa642G0G3grO3Qebc3f1IOcabeEB1sDoyMHf04/CDiasw6MqLxkPME1Jw1ZPz3hp4mc4PPjZ9458axDU0ym1keW8dPow5UVz8rCi2t4HHYD4VxWHFDxm7HTl272zEGiBc9QHwwDJ8ZoRp/9QLukOaMAAZ/FoXBIlMspYFXBlDOCDI3SLzxmfzPPcibA+2Ig2XHISRLttKXBtNq0buZLzErQsFVsdnq94RRrZAKGNV+cQsS3twwct8vvBOyNTbcCXktSHR+1LrVkKrR/CgWszG/e9kVWaO2RL72McBODU0ftX3wQ/5bm8A/RSY0HsgMFBqvHf1LMb1sO71It/jpIsVSfCzF37RSvDQaITpcpmUH/ivegX8w4x748ZaKt9TNu6VmR7SnZm/1k3d2u8XL2Vi+3H75coCu+yo/O9ZQS0mSCzQtrurSKlF0A/Mv0lzE7R7pLFp65RC/QJw+zt4WtCVxs3d5MpHw8/LxJV98yXcdXfK5jCiWk2I5KZaTYjkplpNiOWmgR8hr0dcfG7kjpAAOR9AZYZIcxJDQO3pDQvd64DoSjAh9XQxZECFxwTFW+ptzsveb/9JrjgFl3PlkKswQ/TCzO/Ows1oZXtg9xVf6b9fmtnC7ttUoM6kfBsy48YZ3FfTW5lzKj2ySlEOJs2udV0eZhQ3dWi4HYygLLJyzxIJr+E0avzNjUaZuxKYb8xniaCSiEBmW02R3bQ8idYa2tyJijMrVma3uzagNE4iTjLwvZNe8zCHqgVFc8jJK+o1HSWtBoPzf/LEZlN6KuN+HzSh0sn7g8LIZOhd6kzho4zE4vO3BYX4rxFHwJ/1b0cMKDz0u9gU741VnyGspNHK7J2hZEpSOxLGCz7rDGnbWxT7pCEfmYmAA5hKwpdByf0P1BYP7QdNZ3oy5+GXXu9tg1PZ5b0pFHgAdHQheEj7oHVanwyKycX9L7v7O+bV5qHfODzx3O3DDxiW+efKeS7fryV6lk9E+6+MY0e0WB3TCeYbU33Gk1r6JjKMbgP6rGItVYj9Y0PFD1e3eEHW3XOLB6V0IQqz6Qe4dhsZcFzWQ7HkPHznG+wKgwL5WEJ6Y9a6YRcntwQVWx+WtLMq+uOYVFrwAb+zupZ6IeT4ZEV6+S3zxYUG3NUupB+PWd8l1nimvKPW25pQTNCUvax1M7PPK2Ic2VEUlGiJ8hu4WPZ2CQ+h0/t57er5l4X8/YvbE78Ve4zMqhk1SChaGBkC4DqrveS6UVzbh4HghT94gl2nGkKuWpjEXfxu/6PHZhqwbK/CumloV3hvtlgr0Ri7R1Bn5LNY4Jp81rWVIHBeJCd1Q5aZtiZRZhXappoYRAlOt5Y5c1a2WDYWYZtXSmFqAHqpNnoEJ1azzxAq6qWeaVVEECV4ECVY0hc7rMrqxY313Mos8wTzWDwy2aS1rlqHVYSmTxx44sQD9CKPWP5OJhJsTWw1iq8HN6nb4h4BY8kSE2+EF8ivya/Lm+iATsaUv6RWZ25LpdMm2gQc2NMPmAUxlP2MkToZ/DJ/1YCdD4HIvk1fIq+Q1cok8TXcQpV6VtVUbJtVyyOt0p95otustj38/S55DDlL7F5x+NO2HstAPtsu2fR07Cb4ThYF+J0GA+zPkefICna5auio3gGMD507hC54NpNNyAnD+gmnVKxzOJktvr0vgnwZT1kYugRfyNF2VFRu/BrPK/2ZW5abFgrAsraVX2nhspVtN3QASe5uOnXRo8kGM4lJNOIksODEdOl7HXTSuGEsAIGiFoVjLBv5gf7ZiLWk21lIaAchNHjXhuNChDTvAViDPzYmtS9vtFfhnL5BFCn5gqyQk6yzIswVGNBihmlv3BVkuOwdesoO+ZrX5zJwYt1sUzLkfqyqKyeTWutWB3m5CiiC79j6qEtC69h9UF5IgO9WySe7jGPymU++CeI8beIrnhBv4ufJ0qL8xlDL7wfERudsy1fldT3V+/4ayiA+ZHbBV/cVTQzgX78OO+2k0/j8bGeqWFZ7gt3G8uGP5vt9/9WD8YJeiGrjo9BKCBUS+iwRbwd8GeXWHsW2gq1qeW9H+PTy2b0Au9Xffd9nTxRlMsq4VJbuB6WTrzMjf95vlauGWGmZCdQ09HKcqX8Zhjt6gdcDDtl/ufURPEkytYzvaof8Bm7/DZg==',
                       'case': 'centipede/hybrid/walk',
                       'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                   'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   1.239,
                                   1.239,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                   'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.347,
                                   0.347,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                   'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.615,
                                   0.615,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.678,
                                   0.678,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.759,
                                   0.759,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                   'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   0,
                                   None,
                                   26.09,
                                   1.297,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_phi',
                                   'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   1,
                                   5,
                                   12.992,
                                   0.826,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                   'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                   'float64)',
                                   2,
                                   6,
                                   0.513,
                                   0.513,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                   'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   2,
                                   6,
                                   0.893,
                                   0.33,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                   'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                   'float64, float64)',
                                   3,
                                   8,
                                   0.563,
                                   0.563,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                   'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   2,
                                   6,
                                   10.76,
                                   0.903,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                   'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                   'float64, float64, float64)',
                                   3,
                                   10,
                                   9.856,
                                   2.014,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                   'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, int64)',
                                   4,
                                   11,
                                   7.842,
                                   2.486,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._candidate',
                                   'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   1.824,
                                   1.064,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                   'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   6,
                                   13,
                                   0.76,
                                   0.76,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._descend',
                                   'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                   5,
                                   12,
                                   1.384,
                                   1.384,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                   'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   1.413,
                                   1.413,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                   'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                   'int64, int64, int64)',
                                   5,
                                   12,
                                   0.735,
                                   0.735,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                   'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   1,
                                   5,
                                   11.801,
                                   10.29,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   2,
                                   18,
                                   0.667,
                                   0.667,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   2,
                                   18,
                                   0.844,
                                   0.844,
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
                                   1.949,
                                   1.174,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                   'array(float64, 3d, C))',
                                   1,
                                   21,
                                   0.776,
                                   0.295,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, float64, '
                                   'float64, array(float64, 2d, C))',
                                   2,
                                   22,
                                   0.481,
                                   0.481,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   2.352,
                                   0.567,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.side_sign',
                                   'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                   1,
                                   24,
                                   0.133,
                                   0.133,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                   'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   1,
                                   24,
                                   1.653,
                                   0.592,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_root',
                                   'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   2,
                                   26,
                                   0.789,
                                   0.469,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.matvec',
                                   'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   27,
                                   0.32,
                                   0.32,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                   'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   26,
                                   0.271,
                                   0.271,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                   'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, '
                                   '1d, C))',
                                   0,
                                   None,
                                   0.443,
                                   0.443,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                   'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                   'float64, array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.42,
                                   0.42,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 4d, C))',
                                   0,
                                   None,
                                   1.402,
                                   0.937,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                   'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                   '2d, C), float64, float64, array(float64, 2d, C))',
                                   1,
                                   32,
                                   0.465,
                                   0.465,
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
                                   '3d, C), array(float64, 3d, C), array(float64, 1d, C), float64, '
                                   'StanceArrays(StanceParams(float64 x 5), array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'int64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C))), '
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
                                   464.633,
                                   61.879,
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
                                   158.399,
                                   21.754,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                   'int64)',
                                   2,
                                   35,
                                   2.924,
                                   2.052,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                   'int64, int64)',
                                   3,
                                   36,
                                   0.871,
                                   0.871,
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
                                   10.085,
                                   6.361,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                   'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                   '1d, C), array(float64, 1d, C), float64, float64)',
                                   3,
                                   38,
                                   0.397,
                                   0.397,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                   'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                   'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                   3,
                                   38,
                                   1.763,
                                   0.387,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                   'float64, float64, float64, float64, array(int64, 1d, C))',
                                   4,
                                   40,
                                   1.376,
                                   1.376,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                   'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                   'array(int64, 1d, C), int64, float64, float64, float64)',
                                   3,
                                   38,
                                   0.351,
                                   0.351,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   38,
                                   0.82,
                                   0.82,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                   'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                   '2d, C), float64, float64, float64)',
                                   3,
                                   38,
                                   0.394,
                                   0.394,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.tips_touching',
                                   'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   1.77,
                                   1.77,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                   'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                   2,
                                   35,
                                   0.383,
                                   0.383,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                   'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                   '1d, C), int64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   0.342,
                                   0.342,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                   'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, '
                                   'C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                   2,
                                   35,
                                   17.8,
                                   3.167,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.distance_and_normal',
                                   'bench_myriapoda.world.terrain_kernels.distance_and_normal(int64, array(float64, '
                                   '1d, C), float64, float64, float64)',
                                   3,
                                   48,
                                   12.522,
                                   10.403,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_normal',
                                   'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   4,
                                   49,
                                   2.119,
                                   0.803,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                   'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                   'float64, float64)',
                                   5,
                                   50,
                                   0.82,
                                   0.82,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                   'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   5,
                                   50,
                                   0.496,
                                   0.496,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                   'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64, float64)',
                                   3,
                                   48,
                                   0.974,
                                   0.448,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                   'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                   'float64, float64)',
                                   4,
                                   53,
                                   0.306,
                                   0.135,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                   'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                   'float64)',
                                   5,
                                   54,
                                   0.171,
                                   0.171,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                   'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                   '2d, C), int64, float64)',
                                   4,
                                   53,
                                   0.22,
                                   0.22,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                   'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64)',
                                   3,
                                   48,
                                   0.302,
                                   0.302,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                   'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, '
                                   'C))',
                                   3,
                                   48,
                                   0.836,
                                   0.836,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                   'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                   '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   35,
                                   16.296,
                                   3.091,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   3,
                                   59,
                                   12.785,
                                   12.785,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   59,
                                   0.419,
                                   0.419,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                   'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                   'C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   8.222,
                                   6.289,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                   'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                   3,
                                   62,
                                   0.338,
                                   0.338,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                   'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                   3,
                                   62,
                                   0.309,
                                   0.309,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                   'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   62,
                                   0.36,
                                   0.36,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                   'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                   3,
                                   62,
                                   0.283,
                                   0.283,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                   'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, '
                                   'C), int64, float64, float64, float64, float64)',
                                   3,
                                   62,
                                   0.643,
                                   0.643,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(bool, 1d, C))',
                                   2,
                                   35,
                                   31.538,
                                   4.243,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3), '
                                   'float64)',
                                   3,
                                   68,
                                   24.667,
                                   10.011,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                   'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   4,
                                   69,
                                   14.656,
                                   14.656,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3))',
                                   3,
                                   68,
                                   2.628,
                                   2.628,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                   'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   35,
                                   1.713,
                                   1.056,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_tip',
                                   'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), float64, float64, float64, float64)',
                                   3,
                                   72,
                                   0.657,
                                   0.657,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                   '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                   2,
                                   35,
                                   21.686,
                                   3.71,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                   'array(float64, 1d, C), float64, float64, float64)',
                                   3,
                                   74,
                                   17.976,
                                   17.976,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                   'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   35,
                                   13.554,
                                   11.145,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                   'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   76,
                                   0.556,
                                   0.556,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._wrap',
                                   'bench_myriapoda.kinematics.legs._wrap(float64)',
                                   3,
                                   76,
                                   0.342,
                                   0.342,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._ik_solve',
                                   'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                   'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                   3,
                                   76,
                                   1.512,
                                   1.512,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, '
                                   'C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                   2,
                                   35,
                                   10.332,
                                   10.332,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.carried_boxes.carry_dynamic',
                                   'bench_myriapoda.bodies.carried_boxes.carry_dynamic(CarriedBoxes(array(float64, '
                                   '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                   '2d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 1d, C), float64, StanceArrays(StanceParams(float64 x 5), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C))), array(bool, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(int64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   34,
                                   23.119,
                                   4.896,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                   'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                   '3d, C), float64, array(float64, 1d, C))',
                                   3,
                                   81,
                                   3.005,
                                   1.494,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                   'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, 2d, '
                                   'C), array(float64, 1d, C))',
                                   4,
                                   82,
                                   1.511,
                                   1.511,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.dynamic_stance.push_segments',
                                   'bench_myriapoda.bodies.dynamic_stance.push_segments(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C), StanceArrays(StanceParams(float64 x '
                                   '5), array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C)), float64)',
                                   3,
                                   81,
                                   15.218,
                                   9.504,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.dynamic_stance.foot_forces',
                                   'bench_myriapoda.bodies.dynamic_stance.foot_forces(float64, float64, float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 2d, C), '
                                   'int64, float64, float64, array(float64, 2d, C), array(float64, 1d, C))',
                                   4,
                                   84,
                                   2.621,
                                   2.621,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.dynamic_stance.foot_forces',
                                   'bench_myriapoda.bodies.dynamic_stance.foot_forces(float64, float64, float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 2d, C), int64, '
                                   'float64, float64, array(float64, 2d, C), array(float64, 1d, C))',
                                   4,
                                   84,
                                   3.093,
                                   3.093,
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
                                   211.404,
                                   105.293,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                   'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, '
                                   'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, bool, array(float64, 3d, C), array(float64, 2d, '
                                   'C))',
                                   4,
                                   87,
                                   1.523,
                                   1.523,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                   'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   87,
                                   1.131,
                                   1.131,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   87,
                                   11.066,
                                   11.066,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   87,
                                   14.787,
                                   6.658,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                   'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   91,
                                   8.13,
                                   3.18,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                   'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   92,
                                   4.137,
                                   4.137,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                   'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   92,
                                   0.813,
                                   0.813,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                   'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   4,
                                   87,
                                   9.368,
                                   2.602,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   5,
                                   95,
                                   6.766,
                                   6.766,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                   'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                   'array(float64, 2d, C))',
                                   4,
                                   87,
                                   0.909,
                                   0.909,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                   'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                   '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   87,
                                   2.166,
                                   2.166,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                   'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                   'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   87,
                                   3.045,
                                   3.045,
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
                                   87,
                                   62.116,
                                   20.11,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                   'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   100,
                                   1.159,
                                   0.877,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._cross',
                                   'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                   'float64, float64)',
                                   5,
                                   101,
                                   0.282,
                                   0.282,
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
                                   100,
                                   40.847,
                                   32.941,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                   'C), float64, float64, float64, array(float64, 2d, C))',
                                   5,
                                   103,
                                   0.746,
                                   0.746,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                   'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                   5,
                                   103,
                                   0.673,
                                   0.673,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                   'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, 2d, '
                                   'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   103,
                                   0.611,
                                   0.611,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   5,
                                   103,
                                   1.813,
                                   1.813,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   103,
                                   1.134,
                                   1.134,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                   'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   103,
                                   1.837,
                                   0.855,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                   'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64)',
                                   6,
                                   109,
                                   0.982,
                                   0.646,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                   'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                   'float64, float64, float64, float64)',
                                   7,
                                   110,
                                   0.336,
                                   0.336,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                   'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                   'float64)',
                                   5,
                                   103,
                                   0.5,
                                   0.5,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                   'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                   5,
                                   103,
                                   0.593,
                                   0.593,
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
                                   9.833,
                                   8.306,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, '
                                   'C), float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, '
                                   'C), array(float64, 4d, C))',
                                   2,
                                   114,
                                   1.527,
                                   1.527,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                   'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.439,
                                   1.439,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.energy',
                                   'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.439,
                                   1.438,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                   'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   1.497,
                                   1.497,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                   'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                   'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   0,
                                   None,
                                   1.83,
                                   1.83,
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
 'massspring-legged-dry': {'args': 'eNrtHFuMG1fV67W9j2yS0lDaumVlWQW7xVo52QWFDyTalSuyzlYoLWKVsBpmx+O94/U8Mh5vdpEqIaTsUulK/cjwkz8QL9E3fNHSByJtRSkIRHglQAgfSAi++oWERDnn3nnZM+N9xNmmXXe0zp1zH3PuOeeee8655/arqW9olQT7b9Eu0ru1trokTkm6KU9Z64bcmhKXWpYpSpZNjwgIEUxZ0jWAtSVLN+0LNh2RdGPdlJdteihcGR5QM9ZZwabpB01TXMdWo0ttpWkpGgAz+lJDhs9dsB/ZtB8HlNI1bG6TYZKhd4VGa0liUzRxsIebuojdyITTMaWJqgzo1bHiUzP4FcU6p9QsYlc/S9OCpNdku3pve9M+ZUPjmqLa1SGaaYrrehumOzRru0PcISKiRWegUu5orZSbvd92x5j/XpINgiiSMff75DDJknuqSXIv+SiZDI1xjI9BcvPfdnoXNqETDnEbHTmhWfKybAamQ+6gaUXDeZA7Af1MS1nW5Jr9dXJXNcv75+F78FjQtuy/8BIO3QuExXLECzxlF+CDnApelY1+uofp6NNjOF7lFLOx+AVquqleBqoPOVQ/wqnOCOfxDWj+fYfmFVLwnijuDcdwb9ob6bsu99iTt7A0txGgSwFxBJj/JWhTPs9mUfBnAqU8dnfBed7Nm2WAsMjeDc7FwqbXYQ6eqCmkYqYw403hKT4F/4MF94NlturuCa06WOSWqGgyW3iPtY2mHFx4ab6+EbEKQ0nwUFoqBkjeja0j+w/pelMWtU7ZTy0B1AZhv52T22fx7XxeWB/k8NMOXwzv4TwwGAL5yGeOtch77Xl5jpxmtUAVmpb0tmbZ1ZKD7iId+4Km6NpjqKICCMM8DcYX7FwBlk3S86zhmTC2pUjtUorUF6VIOSxFsrYUIfuLSJpnHNJMLlweTiQY+4oRbUu5aBT6Ce6gwx7CtsJyerfI74qCR/czePoGOBAz9s2UjF0jsNXMZvpBTI4dU4DPJl2zgG0mxKxmHKVl+WqKPI5KehN1QTqVSHAVNdAIA40w0AgfLI3Q08gImwjPeSbCyVSniRDzvS4pH6iQgQoZqJAPmArpB6eYafJ8IF6ySMcfEVW5FudFskZPBB0r1310fbQK8+iiogDJyCiAH3n5joMH+n3oTYc+xRE8yBAE26gbR+Zhm9U0zdQVuVkDl5eO1NY1UVUkcBV1VV4WbZr6imzBP0m1bdMxVVwT6ropyeBt00OK1rJETZIFqSm2wJX+2JKsSURQ101FNPSaOLWk1xRwt50xBd7aphOPssLnRVNUW4jPJL07CHKJnlvLfZJN9AXPFiywvwKLEOUDQQuzepBcLNKMwcekKZVhNIFOvqWIAmCybtORZVNcVSwopfksaMbSzbNtKIxZsmkKK4pWg85YtumwKAEdhrCkmSqU6tCv1VRqOHvyTfItdyIsDsgnsvCJoUQiCC3GTmxn4nuDrV2wI0N9WE990Q2Muz904zfAxQ8hF4eQ7GdB5laB9kPngDnAF1kVLZTLFAFRBfAa/K0iI5U1Gd5HRctyuDyGxaYuiU2bjjcVbUXQ9BoGbFOnWhjmTZ5agvJZSzWgXANBzjiCiVyl98UIsQQTUOQafGMNx5qY5e8PsVfG+ieTiUQQWrx1TIWdjRq5X+9kE+/QVDe4ubkf9ACD1bXt1cWW148Cu5UfyaTFMMBVrLgjXXBiisGo4YHgYUbADac8houdypZ36vDlYMBwJ9HBTkmLkij2tugfYPzZmeI1+u9IW78PbNv+mugt/Ef7Gia5Pv+XSO4ucatiE1XqcETYBJi1gdtuOZJHx3o7Vz92nSv68JZ+0na0BpPSF6Pn4ZtLecdomnOOIMzqgfDEvLA1C1mfuXkha0aIlzxCvLsbseujbX3ju8YufYwAB38Sx8E8UyrlnnE8qGcCme+lNJxlD9962aO83tO5772yd6Gu2Uxf6S2ree+4rMJM8znXbmWzvy1KankXftDypd3qzehTlfD6fdULjrSGYoIj74GITvfbYNmlvTHdj8lsre9ec10a4PkVWBJXQ3tqYxy40/gI/JD/kX+Qd1jTawszkXHuPZD80kBS9lxSSvt8XyntJ3Ou1B9rKtq4WURj8a+unbzwaS8svq8onOsTiXP7fV3m9nrzyQ12n73ffWJt4Ovz17gq2UDrJekFkGnaCY+lJSIqGlSHo8QPxATYMGLbMkxFW55y62x6+FEGmcXRTsrLLNJ2beFqJpHoqigOIm+DyNstFHlzFdZgex1sr4PtdbC97mB7Zfvr9fhoWlTe8QPBXGOgw3FMsx8lU5hff6ebcpzsTDnGZsHj5EvecXIl9A013J2Lvd/99cBp9GkWgTWrYxHBrsZnMKSR56nFjePwwsJeXwsHa4/tIFi700ziUpgGLDj2hhdZfHt7aUPHtynKkcLZMc8bk8yZXq0Zg94M5snPsZT9Ckug5IFZHoJl9xfcrHw3rz8khF6mOeNyGrj8X6BYO5JiNzmXhU3trbjVEkiEj409syMDzCGllX4cGDAx+oUnRhtBorxnCTeMSm/HnBXBStxA4iQjiMPrJumxyKh0r1XH6PBLjw7TOxGOGR/pXzkjqPxuST50hwbD5hGvlcgLQV23UsqOmKNwqPhs2qyjseksEsPJNMkHPsCOlzouKW11Y8lfTaE7Rv6tmCzvxs5gs5udffBaznkPpTy/4RJ/v6jipBcZrI3Brtzg4i67i7vgt+Z3eQr+fSZ3gIJzjFHmi6fo5dy4qUaLdDQ+qWgYr+y41QH/YJox9decqY0ncSvoJKD/6nyLNWI/WGH4d5Gs7jtIbn2Z3z7qYBBy1b/FZDA2FjqkgWTPe/woMMUXIAWOpSI9EXTZwaLijuASy3AVK7tGld/wKue8Gzw43EtdV6I4Ms79oUPO3bmTiiWbYjOYUnZIaHKgsCo227JdTdCUsCKvY+GIV8duOUqiRGRk+CQ97Ix0BnagxWL5/q6LhP5NvNz8b5y1xjHKRyFZDlZ2JpzFZxCQK9UDjTxwsEh+Ri7RjCbUTVn2srRS/G0M03QETNix6QiPBEDlWMtS6nVNxoYjNVE1AAxdTLmFmTt14ZxursCe1vg4SkkBfugBHho4CQPxeAF9JwDZR7kBfw/o+ydicgMuktfJG+TNTUx9ysdEZkxlWakJPKJDxx+0LBAuVdYsnrpX9QF9yQT4bTTWvTMBLhbJy+QV8ip5jfyAPEUniNisC/KaBUi1bPJTelBRjXaz5S2MZ8izmO3VuIQCk/aTuOi7exVAuoVP8i/HcSB8kg90f5o8R56n43VTkQQVVnCTLWiWqmeQ9ZYdoPMXdbNZ43TWWXlvz+1/11uytjq3v1ik6bogWpgRtcb/zawJhsnSD0EfKbU2phymW6CiQMTeokOnbJo8gfmLkm5qsinodZsON3EVDYuuFsMkxBUNf3A8SzSXZQtbiWqAcqOzOuyjqPlYpuEqwFzIwGff66P733vZyGV3+w/udfC+0WnQdNt8EVUAbvwcjSHo3biMW9nf8Oc/zFUOWmQF/3Zzx4hb5E0VnKQoszoemX0DtcwD+lyfkk+Y8f8Hz/j/1/sqoLdLcMDV/qNnSHF1GeKO+/8M4H9ZxpnRCM5knbyoD3O+uN/yM6H+5NH4RIepHQjbewVnrcW+OwU2gyu9cpyi9CPIVeMIiusk/efuuf0+VAdX/Uwez5tgNMm6fmB2C+evBygG6K/72Kpt+ZosAuS6qpynp4Mujcdg7iGWXX9Snvo/93ut4w==',
                           'case': 'centipede/massspring/walk',
                           'events': [('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       1.187,
                                       1.187,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                       'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       0,
                                       None,
                                       30.8,
                                       1.456,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_phi',
                                       'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       1,
                                       1,
                                       15.861,
                                       1.006,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                       'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                       'float64, float64)',
                                       2,
                                       2,
                                       0.501,
                                       0.501,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                       'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       2,
                                       2,
                                       1.0,
                                       0.324,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                       'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                       'C), float64, float64)',
                                       3,
                                       4,
                                       0.676,
                                       0.676,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                       'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       2,
                                       2,
                                       13.354,
                                       0.834,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                       'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       6,
                                       12.52,
                                       2.324,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                       'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                       'int64, float64, float64, float64, float64, int64)',
                                       4,
                                       7,
                                       10.196,
                                       3.279,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._candidate',
                                       'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       1.935,
                                       1.095,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                       'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       6,
                                       9,
                                       0.84,
                                       0.84,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._descend',
                                       'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                       'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                       5,
                                       8,
                                       1.631,
                                       1.631,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                       'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       2.122,
                                       2.122,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                       'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                       'int64, int64, int64)',
                                       5,
                                       8,
                                       1.229,
                                       1.229,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                       'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       1,
                                       1,
                                       13.483,
                                       11.612,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       2,
                                       14,
                                       0.816,
                                       0.816,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       2,
                                       14,
                                       1.056,
                                       1.056,
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
                                       3.603,
                                       2.621,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                       'array(float64, 3d, C))',
                                       1,
                                       17,
                                       0.983,
                                       0.361,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                       'float64, float64, array(float64, 2d, C))',
                                       2,
                                       18,
                                       0.621,
                                       0.621,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, '
                                       'C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       2.745,
                                       0.637,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.side_sign',
                                       'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                       1,
                                       20,
                                       0.17,
                                       0.17,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, '
                                       'C), array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                       'C))',
                                       1,
                                       20,
                                       1.938,
                                       0.671,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_root',
                                       'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                       2,
                                       22,
                                       0.982,
                                       0.518,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.matvec',
                                       'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                       'float64, float64)',
                                       3,
                                       23,
                                       0.464,
                                       0.464,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                       'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                       'float64, float64)',
                                       2,
                                       22,
                                       0.285,
                                       0.285,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                       'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, '
                                       'array(float64, 1d, C))',
                                       0,
                                       None,
                                       0.448,
                                       0.448,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                       'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, '
                                       'C), float64, array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.412,
                                       0.412,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       0,
                                       None,
                                       1.449,
                                       0.997,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                       'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                       '2d, C), float64, float64, array(float64, 2d, C))',
                                       1,
                                       28,
                                       0.452,
                                       0.452,
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
                                       'array(float64, 1d, C), float64, StanceArrays(StanceParams(float64 x 5), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C))), Tuple(Tuple(array(float64, '
                                       '2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), array(int64, '
                                       '1d, C), array(int64, 1d, C), array(int64, 2d, C), array(float64, 1d, C), '
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
                                       199.557,
                                       15.583,
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
                                       137.617,
                                       13.158,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, '
                                       'C), int64)',
                                       2,
                                       31,
                                       3.587,
                                       2.444,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, '
                                       'C), int64, int64)',
                                       3,
                                       32,
                                       1.143,
                                       1.143,
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
                                       13.87,
                                       8.915,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                       'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                       '1d, C), array(float64, 1d, C), float64, float64)',
                                       3,
                                       34,
                                       0.492,
                                       0.492,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                       'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, '
                                       '1d, C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       3,
                                       34,
                                       2.404,
                                       0.417,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, '
                                       'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       4,
                                       36,
                                       1.986,
                                       1.987,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                       'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, '
                                       'C), array(int64, 1d, C), int64, float64, float64, float64)',
                                       3,
                                       34,
                                       0.437,
                                       0.437,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       34,
                                       1.096,
                                       1.096,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                       'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                       '2d, C), float64, float64, float64)',
                                       3,
                                       34,
                                       0.524,
                                       0.524,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.tips_touching',
                                       'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       2.007,
                                       2.007,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                       'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, '
                                       'bool)',
                                       2,
                                       31,
                                       0.322,
                                       0.322,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                       'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                       '1d, C), int64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       0.608,
                                       0.608,
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
                                       25.458,
                                       4.809,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.distance_and_normal',
                                       'bench_myriapoda.world.terrain_kernels.distance_and_normal(int64, '
                                       'array(float64, 1d, C), float64, float64, float64)',
                                       3,
                                       44,
                                       16.9,
                                       14.377,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_normal',
                                       'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       4,
                                       45,
                                       2.523,
                                       1.073,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                       'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                       'float64, float64)',
                                       5,
                                       46,
                                       0.916,
                                       0.916,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                       'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       5,
                                       46,
                                       0.533,
                                       0.533,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                       'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       3,
                                       44,
                                       1.951,
                                       0.847,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                       'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                       'float64, float64)',
                                       4,
                                       49,
                                       0.623,
                                       0.268,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                       'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                       'float64)',
                                       5,
                                       50,
                                       0.355,
                                       0.355,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                       'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                       '2d, C), int64, float64)',
                                       4,
                                       49,
                                       0.481,
                                       0.481,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                       'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, '
                                       'C), array(float64, 2d, C), float64, float64, float64, float64)',
                                       3,
                                       44,
                                       0.499,
                                       0.499,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                       'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, '
                                       '2d, C))',
                                       3,
                                       44,
                                       1.299,
                                       1.299,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                       'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       2,
                                       31,
                                       15.534,
                                       2.831,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       3,
                                       55,
                                       12.38,
                                       12.38,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       55,
                                       0.323,
                                       0.323,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                       'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, '
                                       'C), array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       3.907,
                                       2.148,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                       'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, '
                                       'int64)',
                                       3,
                                       58,
                                       0.192,
                                       0.192,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                       'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, '
                                       'int64)',
                                       3,
                                       58,
                                       0.251,
                                       0.251,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                       'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       58,
                                       0.458,
                                       0.458,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                       'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                       3,
                                       58,
                                       0.252,
                                       0.252,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                       'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, '
                                       '2d, C), int64, float64, float64, float64, float64)',
                                       3,
                                       58,
                                       0.607,
                                       0.607,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                       'array(bool, 1d, C))',
                                       2,
                                       31,
                                       27.338,
                                       2.915,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3), float64)',
                                       3,
                                       64,
                                       22.594,
                                       9.526,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                       'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       4,
                                       65,
                                       13.068,
                                       13.068,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3))',
                                       3,
                                       64,
                                       1.829,
                                       1.829,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                       'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       31,
                                       1.235,
                                       0.765,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_tip',
                                       'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64)',
                                       3,
                                       68,
                                       0.47,
                                       0.47,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                       2,
                                       31,
                                       16.285,
                                       2.652,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                       'array(float64, 1d, C), float64, float64, float64)',
                                       3,
                                       70,
                                       13.632,
                                       13.632,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                       'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       31,
                                       8.295,
                                       7.07,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                       'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), '
                                       'float64, float64, float64)',
                                       3,
                                       72,
                                       0.365,
                                       0.365,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._wrap',
                                       'bench_myriapoda.kinematics.legs._wrap(float64)',
                                       3,
                                       72,
                                       0.172,
                                       0.172,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._ik_solve',
                                       'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                       'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                       3,
                                       72,
                                       0.688,
                                       0.688,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, '
                                       '1d, C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                       2,
                                       31,
                                       6.016,
                                       6.016,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.carried_boxes.carry_dynamic',
                                       'bench_myriapoda.bodies.carried_boxes.carry_dynamic(CarriedBoxes(array(float64, '
                                       '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                       'array(float64, 2d, C), array(int64, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 1d, C), float64, '
                                       'StanceArrays(StanceParams(float64 x 5), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), int64, array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C))), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(int64, 1d, C), array(float64, 2d, C))',
                                       2,
                                       30,
                                       18.101,
                                       3.724,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                       'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                       3,
                                       77,
                                       4.152,
                                       0.752,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                       'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                       '2d, C), array(float64, 1d, C))',
                                       4,
                                       78,
                                       3.4,
                                       3.4,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.dynamic_stance.push_segments',
                                       'bench_myriapoda.bodies.dynamic_stance.push_segments(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(int64, 1d, C), array(float64, 2d, C), '
                                       'StanceArrays(StanceParams(float64 x 5), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), int64, array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C)), float64)',
                                       3,
                                       77,
                                       10.225,
                                       6.73,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.dynamic_stance.foot_forces',
                                       'bench_myriapoda.bodies.dynamic_stance.foot_forces(float64, float64, float64, '
                                       'float64, float64, float64, array(float64, 2d, C), array(float64, 2d, C), '
                                       'int64, float64, float64, array(float64, 2d, C), array(float64, 1d, '
                                       'C))',
                                       4,
                                       80,
                                       1.503,
                                       1.503,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.dynamic_stance.foot_forces',
                                       'bench_myriapoda.bodies.dynamic_stance.foot_forces(float64, float64, float64, '
                                       'float64, float64, float64, array(float64, 2d, C), array(float64, 2d, C), '
                                       'int64, float64, float64, array(float64, 2d, C), array(float64, 1d, C))',
                                       4,
                                       80,
                                       1.991,
                                       1.991,
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
                                       27.481,
                                       13.846,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.massspring.kernels.spring_forces',
                                       'bench_myriapoda.bodies.massspring.kernels.spring_forces(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                       4,
                                       83,
                                       0.252,
                                       0.252,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                       'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                       'array(float64, 2d, C))',
                                       4,
                                       83,
                                       0.139,
                                       0.139,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                       'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64, float64)',
                                       4,
                                       83,
                                       0.309,
                                       0.309,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                       'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       4,
                                       83,
                                       0.43,
                                       0.43,
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
                                       83,
                                       12.507,
                                       3.285,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                       'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       4,
                                       88,
                                       0.305,
                                       0.225,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._cross',
                                       'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, '
                                       'float64, float64, float64)',
                                       5,
                                       89,
                                       0.08,
                                       0.08,
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
                                       88,
                                       8.917,
                                       7.471,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, '
                                       '2d, C), float64, float64, float64, array(float64, 2d, C))',
                                       5,
                                       91,
                                       0.149,
                                       0.149,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                       'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, '
                                       'float64)',
                                       5,
                                       91,
                                       0.133,
                                       0.133,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                       'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                       '2d, C), float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       5,
                                       91,
                                       0.128,
                                       0.128,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64)',
                                       5,
                                       91,
                                       0.316,
                                       0.316,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64)',
                                       5,
                                       91,
                                       0.204,
                                       0.204,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                       'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       5,
                                       91,
                                       0.327,
                                       0.156,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                       'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       6,
                                       97,
                                       0.171,
                                       0.113,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                       'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, '
                                       'float64, float64, float64, float64, float64)',
                                       7,
                                       98,
                                       0.058,
                                       0.058,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                       'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                       'float64)',
                                       5,
                                       91,
                                       0.091,
                                       0.091,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                       'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, '
                                       'float64)',
                                       5,
                                       91,
                                       0.097,
                                       0.097,
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
                                       0.775,
                                       0.473,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, '
                                       '1d, C), float64, array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       2,
                                       102,
                                       0.302,
                                       0.302,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.energy',
                                       'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.28,
                                       0.28,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                       'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                       'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       0,
                                       None,
                                       0.394,
                                       0.394,
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
