"""Compile plans recorded by ``python -m bench_myriapoda.harness.cold_compile --record``: generated, do not edit.

The quick matrix's six compile groups, each compiled in a fresh process with an empty numba cache on the 2-core x86-64 development machine shared with other jobs, numba 0.68.1, Python 3.11.7, 2026-11-27 (python -m bench_myriapoda.harness.cold_compile --record quick --write).  The three legless groups at load average 2-7; the three legged groups again after their chunk's step called rigid_chain.advance_chain directly (no wrapper kernel, the step overload inlined), at load average 9-12 with two recordings side by side: their times are 2 to 6 times those of the first recording (hybrid-legged 216.5 s serial then, 440.7 s now), so compare times within a group, not across.  The times say which kernels are large and which depend on which; the signatures are what the cases ask numba for.
"""
NUMBA_VERSION = '0.68.1'
PLANS = {'fem-legged-dry': {'args': 'eNrtGk1vG0XUSWy3BVRQS2lx28haJDDVyFaTFapvuJWQkOseUJGCUBSt15vMFns32GuRyKpASIkLLEjQLT3AoeTEx4FjzuWjXEDiwG9A3OCAODNvPvZz1vnOoXVGSXbnzXvz5s17b+a9fe9l77x9IUN/5r1SyX3W6neaWlm3u0bZWV02emWt2XO6mu547skF6FnoGrptkb6+7thd77bnHtHt5dWuseS5x5PAJEFreZU+eG6u1u1qqzDqaLNvth3TIp15u3nDINPd9q4NvZteyc21YLiHp3DePZOg1tO1ttYFYq+0bQ3Q8BMcMWtpHYOwtwiAl1SYxXTeMVsO9uovu7kF3W4ZXv1cf+i95pHBLbPj1SfdfFtbtftkuRNXPEHilAaMljghVJxpoeKVFz1Bo/HhJCUCLOJjYn78JH1/yj3yquUYS0Y3xBs+5eZMC5jCpwkv+Z65ZBkt7xY+Uy8wUmfrk/gcPo+n3ZNscjrcnxoXGx+lTFoguFMcN874rI/tjsCeSMG+6GN/zLAdglLBVWjwqLJHrDhJuihEN7qigOonnKcarg4JEiKkCtCc6At7ghGjuuARSV5IQ6Ij6OIABirIW5xMBGcEOQbijxFa6S8oBaIQISuikXWjNTpCCUYF28G6qwzNpxBaDgh1nUIrlKyKVdIJb8oQ/ivrMmFwaStDfwqCJ9WjbIoeqf6OfxroEWNRESwiau9nE/ZO3IujmZZBTf56f7lthE0+xzwLMFajLN3wWeqUSJcQXYqhXrbttqFZUUPNNkmvRyzzhLBMoccn2LoAHlbjz7gaD/zGdm1AGahKm0pHVP3x7FnFhjAoN6fbfcvx6oizi91jr1umbV0H5xhimKxzQPcFkGtks6bdNTrwzSS3SGrgSOrtkNSVIOnWIomBz4NobnPRTM/9MZXJ0O0rScaiopyF/eyOyOEQ+7bicna3zO9Kghcf5e7ZPexACu2D1IxdM7DVytT9ECbjjjpAj1s5P4nwzXqeO613AzeFb4GTHoIvyGUzGeaixh5h7BHGHuHh8ggjLxnJK8Id/4pwNRu9IqTMF9PysQsZu5CxC3nIXMh+7BS9mnweSntg97FrWsdopUWRsQDyrgiUa6QNaDzHQ2Y/Nns8nKwKXXbulvjgGq44flaps92wbBsBWNROJRmj+SBbdZ/L4J77n9S9zsg8wLYci9RbSDt3oKr76O9mhSJsNH4IKUJoj2V7DrF4JZYy+JK+Px9KE+T7QUIPX/gAn6k/E8ksTviZRXyeiP5pxlo/lgTbaPzIGdv0kxU12qr8b4W/KzxPwPJAX9TPcp5iWlelBCp404ENf38fMwFbqhySLXEe1viT0MC5NyZTzvi9uCupyvaletg/9CvC9m1kNGsHQ+BgeJ05qGNqZotYdKPxs9TOOyzHyn7TQ1QCX4cEmhI2m7gA6dLp1fUrcXV17ZH3Vi6sXUHTj7YNEXUPwR1MJd0B/g3fp9B7c39OyiLuQ2AUjY19bOwHYuzyE4weNw/84+Yv/7gZ6+FYDw9GD4uH7VJTz4SNxi9M89fhRJh084um0W7BN/Zm29bfgi9oOtZMi8Dd46bVczRLNxb0ttYjoOeahqXjhc5q19SW7ZZWbtot0+iVF41OWXQStMtA6QpQuWos9SCKujf3z1QmE+0vPZqBhtCFsbMZO5uH29lQb/N7+l1b9sE9HD1nCTOXIHY+ii9AFczpeBXMCX8XLoWLYL7mU6r8e394jpUkOtuYAP0bHx2+lqs0EDiWDARK+F/6jd4gs/xNP6lLAumZHQTSO/14jpKrpxHHt37E8ev2MuWX9uJgI+vcW95T3SJBU2x8Fy4NUWldS41+M2QBGwvNaGmNKEQRxS/ptRQrrCymmiitgUIJyWtNWkEUK6hBfPIB4WoF2tCjiIMhZ33AokwxMatzAWXbUYlTsMZEUVJQmFNgaGQgEuhKCKys+SxVWalNZFEsqTSgULYeRKWMhJSVYDSrPFKCmidBQOHVLrCagViWqFBiadejxHjiSVdaMnSThK3T7ikBFnpRXCnOUp34nunEjRcmMplAZpHyJ+gcBGVSTrw8SsARK4yCjQpqqgZ0Z5TIBuPCmi9ihWpYaKkw/QrIi6GwzLCYntb8AOA+ibyrrACMFlfxtgk5vqDgqhSk80qUK/+lMKoiTdq5ydKHbEamA9EsosLW4D+ikG7GaElAVEGJNQoFVZkDdfxasqqYuyKKAh2uLUjollH+H3z9E5s=',
                    'case': 'centipede/fem/walk',
                    'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                0,
                                None,
                                3.313,
                                3.313,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.93,
                                0.93,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                1.702,
                                1.702,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                'array(int64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                1.407,
                                1.407,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                0,
                                None,
                                80.359,
                                3.353,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_phi',
                                'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                1,
                                4,
                                49.901,
                                2.809,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                'float64)',
                                2,
                                5,
                                1.355,
                                1.354,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                2,
                                5,
                                2.166,
                                0.645,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                'float64, float64)',
                                3,
                                7,
                                1.522,
                                1.522,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                'float64, float64, float64)',
                                2,
                                5,
                                43.571,
                                2.823,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                9,
                                40.748,
                                9.425,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, int64)',
                                4,
                                10,
                                31.322,
                                10.425,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._candidate',
                                'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                7.115,
                                4.151,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                6,
                                12,
                                2.963,
                                2.963,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._descend',
                                'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                4.915,
                                4.915,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                6.162,
                                6.162,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                'int64, int64)',
                                5,
                                11,
                                2.706,
                                2.706,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                1,
                                4,
                                27.104,
                                1.495,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                2,
                                17,
                                25.61,
                                1.815,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, 1d, '
                                'C), float64, float64, float64, float64)',
                                3,
                                18,
                                23.795,
                                18.682,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                4,
                                19,
                                2.146,
                                2.146,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                4,
                                19,
                                2.967,
                                2.967,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                0,
                                None,
                                6.954,
                                1.997,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.side_sign',
                                'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                1,
                                22,
                                0.359,
                                0.359,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, float64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                1,
                                22,
                                4.598,
                                1.836,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_root',
                                'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), array(float64, 1d, C))',
                                2,
                                24,
                                1.999,
                                1.068,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.matvec',
                                'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                25,
                                0.932,
                                0.932,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                'float64, float64)',
                                2,
                                24,
                                0.762,
                                0.762,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, 1d, '
                                'C))',
                                0,
                                None,
                                1.124,
                                1.124,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_poses',
                                'bench_myriapoda.bodies.fem.myriapod.block_poses(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C))',
                                0,
                                None,
                                14.293,
                                2.168,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_centroids',
                                'bench_myriapoda.bodies.fem.myriapod.block_centroids(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C))',
                                1,
                                29,
                                1.153,
                                1.153,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                1,
                                29,
                                10.971,
                                1.599,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                2,
                                31,
                                9.371,
                                9.371,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                'float64, array(float64, 2d, C))',
                                0,
                                None,
                                0.811,
                                0.811,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C), array(float64, 4d, C))',
                                0,
                                None,
                                3.496,
                                2.393,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, 2d, '
                                'C), float64, float64, array(float64, 2d, C))',
                                1,
                                34,
                                1.103,
                                1.103,
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
                                427.805,
                                53.526,
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
                                36,
                                259.794,
                                78.713,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                'int64)',
                                2,
                                37,
                                10.984,
                                7.896,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                'int64, int64)',
                                3,
                                38,
                                3.089,
                                3.089,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_step',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_step(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, array(float64, 1d, C), array(float64, 1d, '
                                'C), array(float64, 3d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                'array(float64, 1d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), array(bool, '
                                '1d, C), array(float64, 3d, C), array(float64, 4d, C), bool)',
                                2,
                                37,
                                30.705,
                                19.912,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                '1d, C), array(float64, 1d, C), float64, float64)',
                                3,
                                40,
                                0.95,
                                0.95,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                3,
                                40,
                                5.134,
                                0.993,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                'float64, float64, float64, float64, array(int64, 1d, C))',
                                4,
                                42,
                                4.141,
                                4.141,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                'array(int64, 1d, C), int64, float64, float64, float64)',
                                3,
                                40,
                                0.911,
                                0.911,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                40,
                                2.557,
                                2.557,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                '2d, C), float64, float64, float64)',
                                3,
                                40,
                                1.241,
                                1.241,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.tips_touching',
                                'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                2,
                                37,
                                3.639,
                                3.639,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                2,
                                37,
                                0.539,
                                0.539,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, 1d, '
                                'C), int64, array(bool, 1d, C))',
                                2,
                                37,
                                1.156,
                                1.156,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                2,
                                37,
                                32.459,
                                13.098,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                'array(float64, 1d, C), float64, float64, float64)',
                                3,
                                50,
                                10.414,
                                4.701,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_normal',
                                'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                4,
                                51,
                                5.714,
                                2.71,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                'float64)',
                                5,
                                52,
                                1.637,
                                1.637,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                5,
                                52,
                                1.367,
                                1.367,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                'float64, float64, float64)',
                                3,
                                50,
                                4.485,
                                2.057,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                'float64, float64)',
                                4,
                                55,
                                1.32,
                                0.619,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                'float64)',
                                5,
                                56,
                                0.701,
                                0.701,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                '2d, C), int64, float64)',
                                4,
                                55,
                                1.108,
                                1.108,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64)',
                                3,
                                50,
                                1.09,
                                1.09,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, C))',
                                3,
                                50,
                                3.372,
                                3.372,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                'array(float64, 2d, C))',
                                2,
                                37,
                                8.65,
                                7.878,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                61,
                                0.772,
                                0.772,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 1d, C), float64, array(bool, 1d, C))',
                                2,
                                37,
                                7.539,
                                4.295,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                3,
                                63,
                                0.434,
                                0.434,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                3,
                                63,
                                0.428,
                                0.428,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                63,
                                0.855,
                                0.856,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                3,
                                63,
                                0.416,
                                0.416,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, C), '
                                'int64, float64, float64, float64, float64)',
                                3,
                                63,
                                1.11,
                                1.11,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'array(bool, 1d, C))',
                                2,
                                37,
                                22.566,
                                9.712,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'float64, UniTuple(float64 x 3), UniTuple(float64 x 3), float64)',
                                3,
                                69,
                                12.854,
                                5.867,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi',
                                'bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi(int64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, '
                                '1d, C), float64, float64, float64, float64)',
                                4,
                                70,
                                6.987,
                                6.987,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C))',
                                2,
                                37,
                                3.265,
                                2.245,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_tip',
                                'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), float64, float64, float64, float64)',
                                3,
                                72,
                                1.02,
                                1.02,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                2,
                                37,
                                9.156,
                                9.156,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                2,
                                37,
                                36.128,
                                30.757,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                75,
                                1.421,
                                1.421,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs._wrap',
                                'bench_myriapoda.kinematics.legs._wrap(float64)',
                                3,
                                75,
                                0.702,
                                0.702,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs._ik_solve',
                                'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, array(float64, '
                                '2d, C), float64, array(float64, 1d, C), float64)',
                                3,
                                75,
                                3.248,
                                3.248,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'bool, array(bool, 1d, C), array(float64, 1d, C))',
                                2,
                                37,
                                14.294,
                                14.294,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.carry_blocks',
                                'bench_myriapoda.bodies.fem.myriapod.carry_blocks(array(float64, 2d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '3d, C), array(float64, 2d, C), array(bool, 1d, C))',
                                2,
                                36,
                                7.867,
                                7.867,
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
                                36,
                                101.169,
                                32.657,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                'array(float64, 2d, C))',
                                3,
                                81,
                                49.981,
                                2.858,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                2.229,
                                2.229,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                22.055,
                                22.055,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                19.905,
                                9.449,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                5,
                                85,
                                10.456,
                                8.208,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                6,
                                86,
                                2.248,
                                2.248,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), array(uint64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                2.934,
                                2.934,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                3,
                                81,
                                12.842,
                                5.565,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                4,
                                89,
                                7.278,
                                7.277,
                                False,
                                True),
                               ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64, float64)',
                                3,
                                81,
                                2.136,
                                2.136,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                3,
                                81,
                                3.553,
                                3.553,
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
                                36,
                                5.45,
                                3.27,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, C), '
                                'float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                'array(float64, 4d, C))',
                                2,
                                93,
                                2.18,
                                2.18,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                1.566,
                                1.566,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                1.898,
                                1.898,
                                False,
                                True),
                               ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), int64, '
                                'int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                0,
                                None,
                                3.058,
                                3.058,
                                False,
                                True)]},
 'fem-legless-dry': {'args': 'eNqNVM2L00AUt902qyAqu66ucVdKDlJlaFkNQm/WBUHKevAuZZqMnSxpUtIJksOCJ6syiuyOoP+t85VJ0jbVDqTvY97v/Wbee/Op9evSuiZ/71m3Sx9E6WwCe16coB7J5mjRg5MFSaBHGN0fC8s4QV4ccVvqkThhV4zuevE8S9CU0VvrznXAaJ5JgdH2MElgJnZdn6RBSIKIG614co54uiv2dskuWJe2fbGd4R1s0cM1tIUHQ5gIsNdhDEUYvqkDWxGcIU7vg3C8cEWWgHwMfILZ6CVtj73YR2x0lC7ZO8Y3+8GMjZrUCmEWp/y4jVOWQxxAQbSrgUDnmQ86p09YjnH2vSlBBEV8I8+Pb0v9Dt19ExE0RUmJGz6g7SASpPB9zsVaBNMI+ewLPhzZCurhqImP8DF+RPdVcrndpMads981SW0eu6NjV4k/N9E/tkQ3aqJPTPQ3FU14SB8PxBKiq0TskHVcUMKtnqhAvdSchniw5EGAQ9likaqiJLFjm0mIYIPCF8gNhUk7lMvevFZhKjFb4JRLixWsegXUeBwuDDS4WzY4SnG40jeFGMqvy/+HUl79AplpIL+ujBarUrry+OHHpf610qKB8dOvvHPvVSapYSYJH+dzdFcVPq1W3ozRH11/ZKg41cZS5xFH1pP1Ko5DBKPqZLUm3Mo4oT0F5+aX0zeoSOTgzKRtqW/OUftAWbG3NcP/G5E6k6KhTlCtiXSVREcqhlFdV4N/jAAoumeV0gZX0UJ2fmFuMd25ajpNM1SdIy/T+WyoK/jVV2BWegX2VDOIYpUfgZ/504J6fwHIYivH',
                     'case': 'worm/fem/flat',
                     'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                 'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 1.562,
                                 1.562,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                 'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.47,
                                 0.47,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                 'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 0.837,
                                 0.837,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.673,
                                 0.673,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                 'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                 'C), float64, float64, float64)',
                                 0,
                                 None,
                                 25.309,
                                 1.228,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_phi',
                                 'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 1,
                                 4,
                                 14.69,
                                 0.701,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                 'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                 'float64)',
                                 2,
                                 5,
                                 0.576,
                                 0.577,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                 'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 2,
                                 5,
                                 1.043,
                                 0.402,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                 'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                 'float64, float64)',
                                 3,
                                 7,
                                 0.641,
                                 0.641,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                 'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 5,
                                 12.37,
                                 0.822,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                 'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 3,
                                 9,
                                 11.548,
                                 2.27,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                 'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, int64)',
                                 4,
                                 10,
                                 9.278,
                                 3.228,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._candidate',
                                 'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 2.096,
                                 1.085,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                 'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 6,
                                 12,
                                 1.011,
                                 1.011,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._descend',
                                 'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                 5,
                                 11,
                                 1.289,
                                 1.289,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                 'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 1.77,
                                 1.77,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                 'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                 'int64, int64)',
                                 5,
                                 11,
                                 0.896,
                                 0.896,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                 'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 1,
                                 4,
                                 9.392,
                                 0.586,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 2,
                                 17,
                                 8.806,
                                 0.606,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, 1d, '
                                 'C), float64, float64, float64, float64)',
                                 3,
                                 18,
                                 8.2,
                                 6.391,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 4,
                                 19,
                                 0.806,
                                 0.806,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 4,
                                 19,
                                 1.003,
                                 1.003,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                 'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, float64, int64, array(float64, 3d, C))',
                                 0,
                                 None,
                                 0.933,
                                 0.392,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                 'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                 1,
                                 22,
                                 0.54,
                                 0.54,
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
                                 47.519,
                                 8.933,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                 'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                 'float64, bool, array(float64, 3d, C), array(float64, 2d, C))',
                                 1,
                                 24,
                                 1.608,
                                 1.608,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 24,
                                 25.422,
                                 0.997,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                 'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 1.151,
                                 1.151,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 11.624,
                                 11.624,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 10.64,
                                 4.688,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                 'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 3,
                                 29,
                                 5.951,
                                 2.189,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                 'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                 'float64, float64, float64, float64, float64)',
                                 4,
                                 30,
                                 3.137,
                                 3.137,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                 'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64)',
                                 4,
                                 30,
                                 0.625,
                                 0.625,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                 'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), '
                                 'array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 1.01,
                                 1.01,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                 'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                 'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                 'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 1,
                                 24,
                                 4.554,
                                 1.053,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 2,
                                 34,
                                 3.501,
                                 3.5,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.segment_spines',
                                 'bench_myriapoda.bodies.fem.body_kernels.segment_spines(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C))',
                                 1,
                                 24,
                                 0.654,
                                 0.654,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                 'array(float64, 1d, C), float64, float64, float64)',
                                 1,
                                 24,
                                 3.774,
                                 1.285,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                 'int64, float64, float64, float64)',
                                 2,
                                 37,
                                 1.116,
                                 1.116,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_normal',
                                 'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 37,
                                 1.373,
                                 0.824,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                 'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                 'float64)',
                                 3,
                                 39,
                                 0.289,
                                 0.289,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                 'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 3,
                                 39,
                                 0.26,
                                 0.26,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                 'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                 'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64, float64)',
                                 1,
                                 24,
                                 1.112,
                                 1.112,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                 'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                 '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                 1,
                                 24,
                                 1.462,
                                 1.462,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity',
                                 'bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 1d, C), float64)',
                                 0,
                                 None,
                                 0.318,
                                 0.318,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.932,
                                 0.932,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                 'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '2d, C))',
                                 0,
                                 None,
                                 0.818,
                                 0.818,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                 'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 1.389,
                                 0.876,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                 'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 47,
                                 0.513,
                                 0.513,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                 'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), float64, '
                                 'array(bool, 1d, C))',
                                 0,
                                 None,
                                 1.367,
                                 1.367,
                                 False,
                                 True)]},
 'hybrid-legged-dry': {'args': 'eNrtHNtuG8eVkkjqUjc1nLpxmVQgFk3Augu5kYjCfCvj1klAOw9GigRI08VyOdQsRe7Sy6VMgjBaFLCYttMCqTdpq9wTp0kvQC/pW9/8Wj8WfStQ9AP6AX1J58zMXqjdJSWKEmJ5vbA01zNnZs6cy8w5+mH6tbtPp9i/l51CgXzZ6Laq6ppmWmjN7rdRZ02tdmxL1WyHPKxAiWIhzTRoWVezTcu57ZBFzWz3LbTpkIfClWGARrvPEg7JlC1L7UOrpWpXb9q6QQuzZrWB6HC3neeGzk2nQDI1aO7gBZwl50LQOpraVC0AdrlpqtANnxId04baQhS9OlR8swij6PYNvWZjp/ItklE0s4acymPdoXPNoY1resupzJNsU+2bXTrduUuOC+KsCogWBCA5v16T85e+5rgwrv5kngEBFPGyOz7+AsufJovPGjbaRFYAN3yWZHQDkMKPUFyyHX3TQDXnFXyukuOgHq3M48fwV/AqeZgPzpp7Q+P81Z/GDJqjfRdE372Ib3i9yZjeczG9n/R6/4z3tmmXC7gEHySLPIklOwxXDsAdnZEP9ecCpzIuDR2Ag6Uh7SzTZA4+ezTDU9BiXBEk5YgM/WS3wC8SFbwqF/3tBTPSZww4XiWSI7DiM3JMTZl+kvcVxW+6C5DbCeAuQWu/hcQ2R77F4Ek+TH8TeXGJd/PGC0wetmCHr7Q09DoU6RdFS+kYWip6u/6qT0uSjzJfNzjzj4bOPGUxtqobiB3757vtJgoe+wznLoBYmaHU8FBqFQLLFnNYnzLNJlKN0cOartJSh57OM+7pdGn5DJ8X1AdJ+ReClAfex/dgwBAoRX5F1qLktefpIkbuoSIZzewatlORBbqYLH/X0E3jeWCQAYTpPAdsX6BzmW7ZKrnFGr4UxlaOPORyJMeTI9mJHLm1csQhfxmW5rZYmtUX/7GQSrHtK0S0lfPRKMyyeGQdjrFsEpYb0yI/1Qo++SAXbxxiB2JgHyVlTI3ApJkVZ7GYHDvGAB1xyoVcwTcrWcG0fuCzKfwKMOkh8IJMOpXiLCrhCAlHSDjCyeIIY5WMsIrwmqciXEmPqggx4+2h8oSFJCwkYSEnjIXMYqeYavJ64OoDk5Xn1Baq7bUiqW4C1SMmlWs4utYZt8EvMLutxCzjm5XTJFvXUbNG7U8ypzlk7rpD5rctmrjhkOUtarS2VFunFWlMW9HiHv2/TS27ut5DNL+k2rZSNWt92hqSTVNTmw5ZaerGlmKYNbg2S1/rwGXb/LUqTV+3W22artnUgCYP6UbHVg0NKVpT7dCmX60iQ8NKq2/patusqWsUtA4WNF0dHdXoSD2AeOoSzz/FsreB8VbnUqlgaeGzwzgPBjWSex2EpY1cvB3yqLsDigJGjr8MkOPIVUWoAIhOZgQnhSvdy7cyv0tg1LgUoXLDPQNTucnl4JXABPt/Y7zA/pUrsMnfIqX1xuyZ7fgtnIZfs934tWe3xN8SPRG4Gcp2/XtcfP7H+FzlS3uviL7IR+uG7jt3xVj3GCsps80L/uSXdTcrufA2FvBdccFTpgRxD24V6aF9ei7KiLrPdmFmF1KjuEUd5qiNkVmOUfUbnhr6r/kYNXQCCxKQD8FI1iNU2vttQw8k6Kcr7kbi3d0/859CTNwXAPa3jIwdvRktiLieMwRGtBAhT6getAOM/xuR0mR9vNx4y5MblyfabPuZHpvH23EC1VXgSkKNK3oc9nNRHFZcobPr85eO7vqcLcQ73kJ8Og2fmaGef3idbUp7J7CD78btYIm9/8lj7xRpPSNIaZx64zP597yVN8deNIyw8gPWxtsi74+n1ZL3dFdmZkZRvLZxqj0dRbVCK2BU+70DaHjr0+h9H3gSsjM3nYQ8ChLdmLW5MKW2vzGLyUzmd3dclTXuSBTw/xpZuj/4v/if+D+s3eqLj2fH6opHR/ZyQibHTibyAy5U5ER5T5T3E6u8y7PRnaNVWSbnP/Tk/PmsK+eTI5UcqZN7pPIzOlP5B13y5o9bvcwn+uXx65djTNzfcNmxA8bJPN4lGfHolNGwqhtQ/gcixbxT4X7V0mtr/EFs5RmWu4I2xRvV7mIq5ZcVkueqo36ucs9WIvoT0Z+I/kT0J6I/Ef1xm8Fk/0fxF/mTHtbTdB0uwrP6Ej4PcVGP7I2LOuMt18VgWNTHYsiiiP4IjtELd+dk73f/rdcdYie4G8VyxJVq4+twoVriERaNJ2iG3bj/KPxOtH6Ad6KDBlTI4TVg9vrvvEeNe/vznry4T1KOJM6ReR6OMosTHTR+HwwXKrLIpTLzI+dvQvz1h4VaucFJbnhTfHxNjwc+lUKhVvCOEpEtR0aU7QmZksXgA4pVD76hwzoOhgL1AX/IcgfmsU9AcgcKefPnGApS80O2crwb8x/KDUf7QMzYLQ+lEg+/GplUWTi9DdioAxYCBqssu6ss+a15bJnkx8C5ANw4NZjNwJ2WG4PGXfGW6OEJOeJBGBm8PK+Ss261Sxf5Xn6D0cQfOU00vg9nMrcXuIfGwA+Es/cGwLn1Mg99g43yo+YGbGekkQ3GuVveEkuMwgJTheF7sF68izv7gUuyLE6vBHF6kV6GrpPXXc8N6d4+nIR2C/g9/D7JGkrdQsghaRvZEFD77ZaiG9s0r5moTvOtbkdrQn2L+Qimrys3oNll5YZpbdHEMyKxqBua0rYtkTLrtHO6jayWQ5Y7W32lrlsdm1ZCmjXLQOoKhVBv8wJIaGaTJ7bBkTHbrosqmuBVNMGqlsG9UQFHR2jvIlPlCRusxMfHW4lbyDJQk05l6fJ3rl6hcISZ+O/5VMotSYyWxGg5qf47fwooW06M/84u/gDfwR8Ox126WPqmXlP47QxZKdu2quEWMlhs/Sqp+AUz8db5czTW4711KKt7A7+J38JvN8DxgJyCaGBbV4Xr9CmsNusK6tkUyY6D3yGf11vtbrODFI2ijsDd2rQ0+jtrm9b1LmLspfEqQMr4PtDk0+O6SvoMu+L8JW57wq44uwWyuGmp27oN3us2sixlSzdqTBBZlOWv1C1dU1qUy1Nun4YMyBPc7wSX/wXTatb48pssfbz+OJ+Mp8ZJ/jh0CTJ1RbUhVrvHf2d7Sttirv0W6ui1Loi6TKdNCdbBH5O5aw6ZfxZiAzSTSi+LSlmHLDTh5C2oxiZdINoLHPy3DPgB8GzV2kQ2tFJbgZVbumRSEaPTPkzobYP/vihJDOLjdsn5q+dFLgf/MEZZaKU5qhwWGdFA/Ig09JVErrsGMrlxf4Vi/4WSGHdUh5TcPyVREshIO0F7IwwmoooWN14HvZv2btyhicYn8OPvzDwOKv/hCY1M1lN1XavOH0sW/3NRJ2/kT1WwaeRcGyk3wTA6+FL6WO93T6LtMGazumYcnw7i07jAZxa0GzwW49d7f6BDFstELSq09n919QqN',
                       'case': 'centipede/hybrid/walk',
                       'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                   'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   2.141,
                                   2.141,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                   'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.794,
                                   0.794,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                   'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.701,
                                   1.701,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   1.094,
                                   1.094,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.171,
                                   1.171,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                   'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   0,
                                   None,
                                   36.567,
                                   2.185,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_phi',
                                   'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   1,
                                   5,
                                   20.785,
                                   1.262,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                   'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                   'float64)',
                                   2,
                                   6,
                                   0.752,
                                   0.752,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                   'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   2,
                                   6,
                                   1.336,
                                   0.474,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                   'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                   'float64, float64)',
                                   3,
                                   8,
                                   0.862,
                                   0.862,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                   'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   2,
                                   6,
                                   17.434,
                                   1.249,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                   'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                   'float64, float64, float64)',
                                   3,
                                   10,
                                   16.185,
                                   3.269,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                   'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, int64)',
                                   4,
                                   11,
                                   12.916,
                                   4.114,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._candidate',
                                   'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   2.849,
                                   1.657,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                   'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   6,
                                   13,
                                   1.192,
                                   1.192,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._descend',
                                   'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                   5,
                                   12,
                                   2.111,
                                   2.111,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                   'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   2.473,
                                   2.473,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                   'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                   'int64, int64, int64)',
                                   5,
                                   12,
                                   1.37,
                                   1.37,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                   'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   1,
                                   5,
                                   13.598,
                                   0.98,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   2,
                                   18,
                                   12.618,
                                   1.047,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   3,
                                   19,
                                   11.571,
                                   9.334,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   4,
                                   20,
                                   1.044,
                                   1.044,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   4,
                                   20,
                                   1.193,
                                   1.193,
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
                                   3.067,
                                   1.773,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                   'array(float64, 3d, C))',
                                   1,
                                   23,
                                   1.294,
                                   0.467,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, float64, '
                                   'float64, array(float64, 2d, C))',
                                   2,
                                   24,
                                   0.827,
                                   0.827,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   3.08,
                                   0.758,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.side_sign',
                                   'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                   1,
                                   26,
                                   0.192,
                                   0.192,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                   'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   1,
                                   26,
                                   2.13,
                                   0.696,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_root',
                                   'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   2,
                                   28,
                                   1.068,
                                   0.566,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.matvec',
                                   'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   29,
                                   0.501,
                                   0.501,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                   'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   28,
                                   0.366,
                                   0.366,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                   'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, '
                                   '1d, C))',
                                   0,
                                   None,
                                   0.579,
                                   0.579,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                   'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                   'float64, array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.504,
                                   0.504,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 4d, C))',
                                   0,
                                   None,
                                   1.801,
                                   1.298,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                   'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                   '2d, C), float64, float64, array(float64, 2d, C))',
                                   1,
                                   34,
                                   0.502,
                                   0.502,
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
                                   375.88,
                                   64.784,
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
                                   36,
                                   95.171,
                                   16.879,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                   'int64)',
                                   2,
                                   37,
                                   5.671,
                                   4.33,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                   'int64, int64)',
                                   3,
                                   38,
                                   1.34,
                                   1.34,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_step',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_step(array(float64, 1d, '
                                   'C), array(float64, 2d, C), float64, float64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), array(bool, '
                                   '1d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(bool, 1d, C), array(float64, 3d, C), array(float64, '
                                   '4d, C), bool)',
                                   2,
                                   37,
                                   16.709,
                                   10.401,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                   'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                   '1d, C), array(float64, 1d, C), float64, float64)',
                                   3,
                                   40,
                                   0.795,
                                   0.795,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                   'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                   'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                   3,
                                   40,
                                   3.075,
                                   0.498,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                   'float64, float64, float64, float64, array(int64, 1d, C))',
                                   4,
                                   42,
                                   2.577,
                                   2.577,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                   'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                   'array(int64, 1d, C), int64, float64, float64, float64)',
                                   3,
                                   40,
                                   0.502,
                                   0.502,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   40,
                                   1.35,
                                   1.35,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                   'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                   '2d, C), float64, float64, float64)',
                                   3,
                                   40,
                                   0.586,
                                   0.586,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.tips_touching',
                                   'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                   2,
                                   37,
                                   2.371,
                                   2.371,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                   'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                   2,
                                   37,
                                   0.463,
                                   0.463,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                   'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                   '1d, C), int64, array(bool, 1d, C))',
                                   2,
                                   37,
                                   0.871,
                                   0.871,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                   'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, '
                                   'C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                   2,
                                   37,
                                   15.026,
                                   5.735,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                   'array(float64, 1d, C), float64, float64, float64)',
                                   3,
                                   50,
                                   5.112,
                                   2.429,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_normal',
                                   'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   4,
                                   51,
                                   2.683,
                                   1.228,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                   'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                   'float64, float64)',
                                   5,
                                   52,
                                   0.852,
                                   0.852,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                   'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   5,
                                   52,
                                   0.604,
                                   0.604,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                   'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64, float64)',
                                   3,
                                   50,
                                   2.283,
                                   0.952,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                   'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                   'float64, float64)',
                                   4,
                                   55,
                                   0.751,
                                   0.364,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                   'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                   'float64)',
                                   5,
                                   56,
                                   0.387,
                                   0.387,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                   'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                   '2d, C), int64, float64)',
                                   4,
                                   55,
                                   0.58,
                                   0.58,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                   'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64)',
                                   3,
                                   50,
                                   0.534,
                                   0.534,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                   'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, '
                                   'C))',
                                   3,
                                   50,
                                   1.361,
                                   1.361,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                   'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                   '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   37,
                                   3.908,
                                   3.509,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   61,
                                   0.4,
                                   0.4,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                   'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                   'C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   2,
                                   37,
                                   5.114,
                                   2.594,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                   'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                   3,
                                   63,
                                   0.249,
                                   0.249,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                   'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                   3,
                                   63,
                                   0.299,
                                   0.299,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                   'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   63,
                                   0.668,
                                   0.668,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                   'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                   3,
                                   63,
                                   0.424,
                                   0.424,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                   'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, '
                                   'C), int64, float64, float64, float64, float64)',
                                   3,
                                   63,
                                   0.88,
                                   0.88,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(bool, 1d, C))',
                                   2,
                                   37,
                                   9.068,
                                   4.069,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3), '
                                   'float64)',
                                   3,
                                   69,
                                   4.999,
                                   2.269,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, float64, float64, float64)',
                                   4,
                                   70,
                                   2.73,
                                   2.73,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                   'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   37,
                                   1.915,
                                   1.153,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_tip',
                                   'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), float64, float64, float64, float64)',
                                   3,
                                   72,
                                   0.762,
                                   0.762,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                   '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                   2,
                                   37,
                                   3.02,
                                   3.02,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                   'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   37,
                                   10.578,
                                   8.805,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                   'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   75,
                                   0.464,
                                   0.464,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._wrap',
                                   'bench_myriapoda.kinematics.legs._wrap(float64)',
                                   3,
                                   75,
                                   0.238,
                                   0.238,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._ik_solve',
                                   'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                   'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                   3,
                                   75,
                                   1.07,
                                   1.07,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, '
                                   'C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                   2,
                                   37,
                                   3.58,
                                   3.58,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                   'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                   '3d, C), float64, array(float64, 1d, C))',
                                   2,
                                   36,
                                   3.301,
                                   1.579,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                   'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, 2d, '
                                   'C), array(float64, 1d, C))',
                                   3,
                                   80,
                                   1.721,
                                   1.721,
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
                                   36,
                                   202.167,
                                   91.739,
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
                                   1.507,
                                   1.507,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                   'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   1.376,
                                   1.376,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   15.05,
                                   15.05,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   17.68,
                                   6.922,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                   'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   86,
                                   10.757,
                                   3.186,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                   'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   87,
                                   4.153,
                                   4.153,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                   'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   87,
                                   3.418,
                                   3.418,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                   'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   10.467,
                                   2.543,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   5,
                                   90,
                                   7.924,
                                   7.925,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                   'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                   'array(float64, 2d, C))',
                                   4,
                                   82,
                                   1.114,
                                   1.114,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                   'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                   '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   82,
                                   2.482,
                                   2.482,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                   'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                   'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   82,
                                   3.107,
                                   3.107,
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
                                   57.644,
                                   17.698,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                   'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   95,
                                   2.635,
                                   1.957,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._cross',
                                   'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                   'float64, float64)',
                                   5,
                                   96,
                                   0.679,
                                   0.679,
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
                                   4,
                                   95,
                                   37.311,
                                   27.924,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                   'C), float64, float64, float64, array(float64, 2d, C))',
                                   5,
                                   98,
                                   0.888,
                                   0.888,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                   'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                   5,
                                   98,
                                   0.823,
                                   0.823,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                   'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, 2d, '
                                   'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   98,
                                   0.756,
                                   0.756,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   2.04,
                                   2.04,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   1.279,
                                   1.279,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                   'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   2.319,
                                   0.984,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                   'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64)',
                                   6,
                                   104,
                                   1.335,
                                   0.91,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                   'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                   'float64, float64, float64, float64)',
                                   7,
                                   105,
                                   0.425,
                                   0.425,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                   'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                   'float64)',
                                   5,
                                   98,
                                   0.574,
                                   0.574,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                   'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                   5,
                                   98,
                                   0.709,
                                   0.709,
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
                                   36,
                                   10.457,
                                   7.667,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, '
                                   'C), float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, '
                                   'C), array(float64, 4d, C))',
                                   2,
                                   109,
                                   2.79,
                                   2.79,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                   'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   2.749,
                                   2.749,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.energy',
                                   'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   2.792,
                                   2.792,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                   'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   3.197,
                                   3.197,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                   'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                   'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   0,
                                   None,
                                   3.605,
                                   3.605,
                                   False,
                                   True)]},
 'hybrid-legless-dry': {'args': 'eNrtGU1vG0U0TmwnKaVULYXiNihaCWTQKqWpVck33EKgctNDVURQaVfr3bFnmvXudnacxAdUTgmgASG6SHxTCN9/gT/AoUeuSBzLH+DCobyZ/fCuvXbzUYoK9UrrN29m3rx537PzZv7DP2bG5O+SXy7zJ+xOu6HPGQ5Fc6zrIm9Ob3iM6gbz+UFNYDSKDMcGXMdgDvWv+3zScNwuRS2f7xvsHCRou10J+LxQo1TvilFTjQ6xGLEBWXQaVxAsd90/t+G/4Zd5wRTDfTyBi/zwADXP0C2dCmILlqOLaXhvODFv620E7DVFx8mKWIWwVWIy7Nef5wXNcEzk1492NvzzPgw2Sduvj/OipXedDmw3d9qPSBzSBaPlkJA6O2+qs6ef8SMai++OSyKCRTwdrY8fke39fPKMzVAL0QRv+BAvEFswhR8HXooeadnI9N/Ch+ulgNSR+jg+imfwk/xgsLgcHi+NZxc/GrJoCeZOhHP7GT8Rz35vxOzckNnH49nvBLMZTDmGq+IRYCUAscIG6aoJuukd9ah+EPJUw9UNX9DBygZMVgEsiYelGwEkRoxCCVDNaMCjRogeKuwIukrZTz+Z1JwR5IKuEEzRGt5Qh/TU4FHipxL+gxZEaz3BuyJGC9c5MuA64KlMJzaS3nOh41oo6T2FwEnLkrAKahaLCK1ejLV6uafymnxXwG0KhtOxmV+fSjoufo1Pv2ITx74gMAk/uCxm4dpG7GoLctjFTMtTM61ZzbCmSz3f/CQ0KsJ/lnssZxOZzV5xR+gUK7ukHLAH7rG8+Gm4k2qo7ZSLpaT9dCLOFDu9QIOffRsizGOpiJeLIx6eiZTwaMBEJ+2hsUg/Dhm5Js2wJtWffCsyAjTqJWxIdlDSYlzJP+gcTOqa8AZMll7KjY0Fer+PVaRuyWbnt2nJakb0V7PUo8rWJWEon0Umv/Tb+NhYpkjns7cSoUPKWWvPbk050ej7WaFbHD6/C3Qnk+9s7C6R2xHcv09ga2KUcfHzRCmTSE5BjtwQgWhiMBBBDKqti6zwXGbCmR+RWmDJL+KkspA08B2IIrGPL7P3UY7TfHUw7PeKzFOOYyHdTheZ+QZgfYj5B6KqMqrBDgR8iP5kCfZ+yEMlDuIPZQXxzSCIi+DNLyYFmKS3+4AoZX0jlvXtnYSyXaF34/EpUWwzag43kq+GGUlVlsZqUIuD3ooZNg/90uaVUUVWL498HUveyZT88axssc3eTLTc6eZod6jGdW8N/iuyElXCw0ejvj/LasPCQ1rt69uoM+e3XX0C+9/ESdjL7SwJ/xMmemIXS44OZCfuBvr43du6tKFv45JZDc9BcBLZcw6KXLP/wBNZVnTUceM6+9qdC11ebBJkmXBc4rk1n+dWfF60tSZFUEznGWLiu8YLbY3Y0JE3HNSEdrvjGZbob+se9Oevaqti2IK26tBlAF4OgUliG5rLaAg5TZicdxFt+3zaW+5qTUI9OHdNClgOKwjoLFBougFCAAbkAQms6AJwm2EXAEEXALJr2oYaX7OILXhoRsw0AgDW2Udsj+m2gTTDkow/1UC2gbV2lxLddUx9ruGYBI6XuNugxJxbRtRGFoybWnhx8SyQ9YTQydLvUJpGmAfV6YPq9L9anX6XSGO/DKlOb/JCk6whE5xEZ0wDB+qCIwrQcgxwShh2iytD/IySFjE1A+vE9vmeGmO6gdvIlp9CCa/3EHelSP0+ezv9RepmqoK8CWHRgLB41efjKxB1cqs+/pXvFd+eGNHD/e7FutXU0BoDViFcTC9Dd1tnBCY+TNpux/Ig5MBWIGQWmg414L/IHHq1gyAs4Vv4T1445ayhILzw2xL+f9eKPwzT1WCtCBqabFF9hTBheQxRqoH8TZm9KGhsT5MSQ2tDaoAUkRcNkYRw14tl/6pDLTOQvSPhe1st/jjaLu9ULcL+C00NPA6May34L65pLpU+SZFHzI5IjgXPBasEKz7fACs+D8CZVZCX4UCOo5CafT5hCTec0O0WCAgmujBm2RYvQZLptIWYGKW3I8lNnXYgCxGYIPPiClSLEeZBwXivC8af0gVj+vO2gkv4hjAj+Zn9WHA7Eca94G4i0SiNuj7YOlIJ100XoEp0B1ANmVHW+y9KUncH6h2uSNTe7UI/AxldAv2XWPTKPjDWKzPidRJewS1Q4mKib1cpGcXltXDMUhiOovuSUsh8hsMGiyjJ6w0l3lsp2lspHjFayCPkPry/t5etKjiBSnKpyLNGNdpFTy4x6lhkgkFTDaW0mZxQgWwbClHaQnU97KzGugjCnySD5v4GheWbUw==',
                        'case': 'chain/hybrid/fig4-drop',
                        'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                    'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.377,
                                    1.377,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                    'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.296,
                                    0.296,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                    'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.562,
                                    0.562,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.421,
                                    0.421,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.486,
                                    0.486,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                    'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    0,
                                    None,
                                    17.739,
                                    0.941,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_phi',
                                    'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    1,
                                    5,
                                    10.192,
                                    0.6,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                    'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                    'float64)',
                                    2,
                                    6,
                                    0.36,
                                    0.361,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                    'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                    'float64, float64)',
                                    2,
                                    6,
                                    0.608,
                                    0.222,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                    'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                    'float64, float64)',
                                    3,
                                    8,
                                    0.386,
                                    0.386,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                    'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    2,
                                    6,
                                    8.624,
                                    0.604,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                    'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                    'float64, float64, float64)',
                                    3,
                                    10,
                                    8.02,
                                    1.682,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                    'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, int64)',
                                    4,
                                    11,
                                    6.338,
                                    2.358,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._candidate',
                                    'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    1.334,
                                    0.775,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                    'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    6,
                                    13,
                                    0.559,
                                    0.559,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._descend',
                                    'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                    5,
                                    12,
                                    0.918,
                                    0.918,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                    'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    1.125,
                                    1.125,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                    'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                    'int64, int64, int64)',
                                    5,
                                    12,
                                    0.604,
                                    0.604,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                    'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                    'float64, float64, float64, float64)',
                                    1,
                                    5,
                                    6.606,
                                    0.53,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                    'float64, float64, float64, float64)',
                                    2,
                                    18,
                                    6.076,
                                    0.462,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, '
                                    '1d, C), float64, float64, float64, float64)',
                                    3,
                                    19,
                                    5.614,
                                    4.581,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    4,
                                    20,
                                    0.433,
                                    0.433,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                    'C), float64, float64, float64, float64)',
                                    4,
                                    20,
                                    0.599,
                                    0.599,
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
                                    1.81,
                                    1.046,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                    'array(float64, 3d, C))',
                                    1,
                                    23,
                                    0.763,
                                    0.26,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                    'float64, float64, array(float64, 2d, C))',
                                    2,
                                    24,
                                    0.504,
                                    0.504,
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
                                    98.901,
                                    6.408,
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
                                    26,
                                    92.493,
                                    39.108,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                    'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, '
                                    'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), float64, bool, array(float64, 3d, C), array(float64, 2d, '
                                    'C))',
                                    3,
                                    27,
                                    0.758,
                                    0.758,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                    'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    27,
                                    0.666,
                                    0.666,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    27,
                                    7.96,
                                    7.96,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    27,
                                    9.149,
                                    2.791,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                    'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    4,
                                    31,
                                    6.358,
                                    2.008,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                    'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    5,
                                    32,
                                    3.475,
                                    3.475,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                    'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    5,
                                    32,
                                    0.875,
                                    0.875,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                    'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, '
                                    'C), array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    3,
                                    27,
                                    3.687,
                                    0.938,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    4,
                                    35,
                                    2.75,
                                    2.75,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                    'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                    'array(float64, 2d, C))',
                                    3,
                                    27,
                                    0.428,
                                    0.428,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                    'array(float64, 1d, C), float64, float64, float64)',
                                    3,
                                    27,
                                    3.051,
                                    1.083,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    4,
                                    38,
                                    0.658,
                                    0.658,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_normal',
                                    'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    4,
                                    38,
                                    1.31,
                                    0.589,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                    'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                    'float64, float64)',
                                    5,
                                    40,
                                    0.414,
                                    0.414,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                    'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    5,
                                    40,
                                    0.307,
                                    0.307,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                    'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                    '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    27,
                                    0.904,
                                    0.904,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                    'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                    'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    27,
                                    1.127,
                                    1.127,
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
                                    27,
                                    25.655,
                                    9.294,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                    'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    3,
                                    45,
                                    1.075,
                                    0.894,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._cross',
                                    'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                    'float64, float64)',
                                    4,
                                    46,
                                    0.18,
                                    0.18,
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
                                    45,
                                    15.286,
                                    10.976,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                    'C), float64, float64, float64, array(float64, 2d, C))',
                                    4,
                                    48,
                                    0.352,
                                    0.352,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.matvec',
                                    'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    4,
                                    48,
                                    0.316,
                                    0.316,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                    'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                    4,
                                    48,
                                    0.272,
                                    0.272,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                    'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                    '2d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    4,
                                    48,
                                    0.306,
                                    0.306,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    4,
                                    48,
                                    0.637,
                                    0.637,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    4,
                                    48,
                                    0.402,
                                    0.402,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                    'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    4,
                                    48,
                                    0.406,
                                    0.406,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                    'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    4,
                                    48,
                                    1.223,
                                    0.335,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                    'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    5,
                                    56,
                                    0.888,
                                    0.605,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                    'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                    'float64, float64, float64, float64)',
                                    6,
                                    57,
                                    0.284,
                                    0.284,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                    'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                    'float64)',
                                    4,
                                    48,
                                    0.181,
                                    0.181,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                    'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                    4,
                                    48,
                                    0.215,
                                    0.215,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                    'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.981,
                                    0.981,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.energy',
                                    'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.99,
                                    0.99,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                    'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.083,
                                    1.083,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                    'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                    'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                    0,
                                    None,
                                    1.364,
                                    1.364,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                    'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                    0,
                                    None,
                                    2.169,
                                    1.045,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                    'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                    '2d, C), array(float64, 1d, C))',
                                    1,
                                    65,
                                    1.125,
                                    1.125,
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
                                    1.546,
                                    1.546,
                                    False,
                                    True)]},
 'massspring-legged-dry': {'args': 'eNrtG0tsG8eVpEhKst3EiGHEZVKBIAqQDQiBsYQiuTURECIgnYObogYiY7PkLjVLkbv0cChLh6JFAItFPTWQel33m19boG6BFm2atDACJL23t156b265tPcifW9mf+TukpJMq0FELyzN9837zZs3b56+k77zr2cT4t9Vu8S/aA66DXW1aVF9le319P6q2ugzqjaZzc8p2KJQvWmZ0DZoMovat22+2LR6e1Tfsvkj4c4wQLO3Jwo2zzxHqbqHo5YaA6PDDBMas1ajrcNyt+2Xhva3AKWMhsNtskCy/EIIWr+pdlSKwF7oWCpOI2eciWlT7eqAXgs7vrqOqxjsuqExYte+xjNK09J0u/bkYGhftmGwZnTtWpJnO+qeNQBykxu2C+K8ioiWHEDl/NNaOb/xFduFcen7KQEEUSTL7vrkUZIjT9RS5EnyJbISgnFRwiD5S99zZheHMAlBnOWLL5pM39JpgBxynmcME+kgjwP62b6xZeqa/V1yoZaT8wuwHnwMxlb8iiwh6ElNWKxEVOCruA1+k9Mhu3LR3ziYkTkTwMkupzgCK75SiekZl0cF5JF05HFOykOw1JMoSOOWI40qKXpflFwXYuS65kHirlzFV2BYqu8HOFZEHKHNXwnGVG4IKoo+JVAq4HS3uSCneVQGWI6C35fyLQ69CXX4okhIx5Cw7pHwuiTBX7DoLlgR+/GJ0H6E7c9Uw9TFlnx50OvowS2ZkTsfEasKlFQPJa0UYPk4ts6ueN6yOrpqju6KdANabdgGj0l2+yJ+TNKF/UEJ/8CRC/U+KQMqEChEfnUxouCNl+U62RS9wBWeaVoDk9m1soOuwpe/YRqW+TIarwDCQCcVcsHJVRDZCr8hBr4SxrYcaXfKkZakHKmH5UjRliN0/yqy5rbDmpUr/1hIJIT4ShFjy/loFGbZPMKHY2ybhuXaUZE/EgefPsnNaw8ggRjYD1MzjozANMrWZ8FMiZ0wgHbKdRjEYUJYLesYrR3fTJFvo5Eeoi3IpBMJaaLmFmFuEeYW4fNlESY6GWEX4Y7nItTToy5CzHpjWj43IXMTMjchnzMTMgtJCdfkh4FIisJPvaR2dS3uFikG3QxerNzro3tHq4obXVQUIBUZBfBjMjcdPPDeVxA3a1Y7y7MtQ+9ocH/lyabNk9dsntqhULhu8+VtuPR2VWZAR5rAKGjehf87cDNsGbs61JdUxpSGpe3BaCx2rKbasfmpjmFuK6alYUgsfbmPgbTU5QaUr7FuD8oagws4f8Qw+0w1m7rS7Kh9GPrlhm42idLdo4baszR1FUAbeAMHkgxdg5V2EeKZDVl/XlRvo+FuJBOJYGvps2N4Dwc10vodxiSOyP0BTYW7oNMg1OhuQJ39UMetUrgB1bUiwiJVcscJOgTDCqeDcdCAn35LBnlwUoV5ActXgxGFw4QPRpkXxSRRu+rHPt9zSLzPP4l0BqYI0gF+GA9ieuPDPPe8e9QHl96PlK4mzc4QTcZCxL0KhLWPUZ9KpIwuTva+fu56X/yFqY7UQTaC0NI3ounw7WnBsap1J0bJaqfDhHlxLRHTeuXhxbQEI970GPHpUdRuhofvgxvCIzohAQm+FSfBgjAqlYkXfegXClmYZDScbQ9rve1x3pro/U/e2QfZ91EOwjuTdbXgxdOr4uyuOyFwqbVno7RWTpGR2M2j2s3osGt4//7Cuz31kzG3p/+Diq7N+gw+4hG6Ngtiptu7X7rxL5D5e7Al3g+fqR+Tf5N/kr+Sv4tB96+sR4bAjkHny3MdOXYdKZ/wE6V8khy58mz8qGi35iq6iX92PeQrz3oRsxPF4fyMWJw/6fsyf9yHT35++hz/6RPr/X5w6S/SlOyj35LywlE848R6Mk2iGiZ0h6NFT8VEi7rQ2+9Rw9xadfts/ujXRcsGQqvrWyJsdP/K7zKJxFhHaR5GethhJHcPzk+M+YkxPzHmJ8YhTgxxZHwYHxqKyrJ7KphZB3x4BtNNl8gq5pk+7ibYpUYT7HBY8PHk197jSTW0hhWeLtXen34v8PayKcKJrLYcEblpX0gmEiI3b5NU2+egImI4r4UjjxcPEXk8bN5cOcwDEen5jRcm+9vBHsmfOaAqRyrnCJ0Pppnrk0YLAf02mBVaFwmqVZEuJKOMMp4o8njdHFQ3izU+jdKS+a2FUB4vRuYiqtXIdOWxzNiKszgFrCz8hraYSIcO6lSGRt2FZYorqtxICvW0fGqfxlAGtJ+Zm5PTxDNPbjg6B1ODb3goFWSW7QhRVedVk4pVqcj0RS5XXC4X/dEyhbjoJ1i7AIpOcBSpoS5ZbqqxfHFdgs0z/t4qsoXxLWOFn3e7Xb3I7+bXhE78XupEu4Z7MjcO3EOD+vnObDzP2e2vyAxnFJSfHE2FZIojAia5Gx6Li0LDAqTi8hbyS05xqaeuyop07MK+kyV+8wBvceBznyb/LZE3yJs8ayotqus2T3eFe52WtWV8xlXwQdfmi9Kths7lPjNaLVPHgYua2u1BM0yhep/Z4MQr1y26DbupnQTetVPwg5+WfnYdAEnnm/8n0HKCntg+CpxeN2Oe2O6St8jb5B2o3eOFmGsONbYMTZHXI37qOcbUJunqpvh7kRVe8xtm8qD2h2isJz+o3S2RH5Efk5+Qn7pKdQbz6JmhOkkDZ4jaaSn6LgM0+zb5Gf+C0e0NOn244wHyOiYaWLQJv7PMotcGOqgUudc2UZ8y/us///S4Lmuf4feyP8YJKPxedrfEF7eoumMwzNtgOqXKtmHCJTmNZVCmFjWaShf2fUeYAZEA0iN7/SD7v2nRjibZb4ny8T6avTtZH6c9mgELMi1FZZiOsCt/Z3eVHhVJLWDFDG2AiSyZPhg23Sa/4snLNk+9iFkxTYuCDitWy+YLHdx7C6pr+zC1ZdvEHwiPqXRLZzhK7QY4t7RhwXGD9lJkruxg5orTMr9jHPe72Z+8vPGKe6gGj0eo7wd9pbA3FNEFzW18CsXZ7dfwAHwdf9wTrn3QcSn6f3s0AnHUpBY9j9Rfq+L8z0Wp+MhfUwkycq5/l5vi1E1oimn0sY7tOpAPKfxt1wWV5GwG3Rxv+0o3sOI6jfrq/wBMdfL3',
                           'case': 'centipede/massspring/walk',
                           'events': [('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       2.668,
                                       2.668,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                       'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       0,
                                       None,
                                       43.026,
                                       1.729,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_phi',
                                       'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       1,
                                       1,
                                       28.809,
                                       0.971,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                       'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                       'float64, float64)',
                                       2,
                                       2,
                                       1.422,
                                       1.423,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                       'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       2,
                                       2,
                                       2.097,
                                       0.737,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                       'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                       'C), float64, float64)',
                                       3,
                                       4,
                                       1.359,
                                       1.359,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                       'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       2,
                                       2,
                                       24.319,
                                       0.995,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                       'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       6,
                                       23.324,
                                       3.629,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                       'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                       'int64, float64, float64, float64, float64, int64)',
                                       4,
                                       7,
                                       19.694,
                                       5.736,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._candidate',
                                       'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       5.003,
                                       2.79,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                       'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       6,
                                       9,
                                       2.214,
                                       2.214,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._descend',
                                       'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                       'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                       5,
                                       8,
                                       2.572,
                                       2.572,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                       'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       4.397,
                                       4.397,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                       'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                       'int64, int64, int64)',
                                       5,
                                       8,
                                       1.987,
                                       1.987,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                       'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       1,
                                       1,
                                       12.488,
                                       0.697,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       2,
                                       14,
                                       11.792,
                                       0.803,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       3,
                                       15,
                                       10.989,
                                       8.478,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       4,
                                       16,
                                       0.927,
                                       0.927,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       4,
                                       16,
                                       1.584,
                                       1.584,
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
                                       3.004,
                                       1.853,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                       'array(float64, 3d, C))',
                                       1,
                                       19,
                                       1.152,
                                       0.424,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                       'float64, float64, array(float64, 2d, C))',
                                       2,
                                       20,
                                       0.727,
                                       0.727,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, '
                                       'C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       3.459,
                                       0.929,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.side_sign',
                                       'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                       1,
                                       22,
                                       0.186,
                                       0.186,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, '
                                       'C), array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                       'C))',
                                       1,
                                       22,
                                       2.345,
                                       0.839,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_root',
                                       'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                       2,
                                       24,
                                       1.151,
                                       0.574,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.matvec',
                                       'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                       'float64, float64)',
                                       3,
                                       25,
                                       0.577,
                                       0.577,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                       'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                       'float64, float64)',
                                       2,
                                       24,
                                       0.355,
                                       0.355,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                       'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, '
                                       'array(float64, 1d, C))',
                                       0,
                                       None,
                                       0.913,
                                       0.913,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                       'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, '
                                       'C), float64, array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.571,
                                       0.571,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       0,
                                       None,
                                       3.181,
                                       2.154,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                       'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                       '2d, C), float64, float64, array(float64, 2d, C))',
                                       1,
                                       30,
                                       1.027,
                                       1.027,
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
                                       768.614,
                                       103.843,
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
                                       32,
                                       253.993,
                                       56.929,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, '
                                       'C), int64)',
                                       2,
                                       33,
                                       7.151,
                                       5.046,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, '
                                       'C), int64, int64)',
                                       3,
                                       34,
                                       2.106,
                                       2.106,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_step',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_step(array(float64, '
                                       '1d, C), array(float64, 2d, C), float64, float64, array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(bool, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C), bool)',
                                       2,
                                       33,
                                       26.52,
                                       14.288,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                       'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                       '1d, C), array(float64, 1d, C), float64, float64)',
                                       3,
                                       36,
                                       1.116,
                                       1.116,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                       'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, '
                                       '1d, C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       3,
                                       36,
                                       7.042,
                                       2.534,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, '
                                       'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       4,
                                       38,
                                       4.508,
                                       4.508,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                       'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, '
                                       'C), array(int64, 1d, C), int64, float64, float64, float64)',
                                       3,
                                       36,
                                       0.87,
                                       0.87,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       36,
                                       2.251,
                                       2.251,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                       'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                       '2d, C), float64, float64, float64)',
                                       3,
                                       36,
                                       0.954,
                                       0.954,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.tips_touching',
                                       'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                       2,
                                       33,
                                       3.876,
                                       3.876,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                       'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, '
                                       'bool)',
                                       2,
                                       33,
                                       0.927,
                                       0.927,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                       'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                       '1d, C), int64, array(bool, 1d, C))',
                                       2,
                                       33,
                                       1.526,
                                       1.526,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                       'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, '
                                       'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'float64, float64, float64, float64, array(float64, 2d, C), array(float64, '
                                       '3d, C))',
                                       2,
                                       33,
                                       38.459,
                                       13.823,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                       'array(float64, 1d, C), float64, float64, float64)',
                                       3,
                                       46,
                                       11.07,
                                       5.332,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_normal',
                                       'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       4,
                                       47,
                                       5.737,
                                       2.26,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                       'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                       'float64, float64)',
                                       5,
                                       48,
                                       2.043,
                                       2.043,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                       'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       5,
                                       48,
                                       1.435,
                                       1.435,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                       'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       3,
                                       46,
                                       7.491,
                                       2.957,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                       'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                       'float64, float64)',
                                       4,
                                       51,
                                       2.614,
                                       1.108,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                       'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                       'float64)',
                                       5,
                                       52,
                                       1.506,
                                       1.506,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                       'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                       '2d, C), int64, float64)',
                                       4,
                                       51,
                                       1.921,
                                       1.921,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                       'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, '
                                       'C), array(float64, 2d, C), float64, float64, float64, float64)',
                                       3,
                                       46,
                                       1.361,
                                       1.361,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                       'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, '
                                       '2d, C))',
                                       3,
                                       46,
                                       4.713,
                                       4.713,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                       'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       2,
                                       33,
                                       5.619,
                                       5.1,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       57,
                                       0.519,
                                       0.519,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                       'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, '
                                       'C), array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       2,
                                       33,
                                       8.032,
                                       4.051,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                       'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, '
                                       'int64)',
                                       3,
                                       59,
                                       0.459,
                                       0.459,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                       'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, '
                                       'int64)',
                                       3,
                                       59,
                                       0.565,
                                       0.565,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                       'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       59,
                                       1.101,
                                       1.101,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                       'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                       3,
                                       59,
                                       0.653,
                                       0.653,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                       'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, '
                                       '2d, C), int64, float64, float64, float64, float64)',
                                       3,
                                       59,
                                       1.203,
                                       1.203,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                       'array(bool, 1d, C))',
                                       2,
                                       33,
                                       21.331,
                                       11.676,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3), float64)',
                                       3,
                                       65,
                                       9.655,
                                       3.306,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, float64, float64, float64)',
                                       4,
                                       66,
                                       6.349,
                                       6.349,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                       'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       33,
                                       5.465,
                                       2.957,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_tip',
                                       'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64)',
                                       3,
                                       68,
                                       2.509,
                                       2.509,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                       2,
                                       33,
                                       11.088,
                                       11.088,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                       'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       33,
                                       48.053,
                                       41.873,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                       'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), '
                                       'float64, float64, float64)',
                                       3,
                                       71,
                                       1.869,
                                       1.869,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._wrap',
                                       'bench_myriapoda.kinematics.legs._wrap(float64)',
                                       3,
                                       71,
                                       0.707,
                                       0.707,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._ik_solve',
                                       'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                       'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                       3,
                                       71,
                                       3.604,
                                       3.604,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, '
                                       '1d, C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                       2,
                                       33,
                                       19.017,
                                       19.017,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                       'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                       2,
                                       32,
                                       13.265,
                                       6.157,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                       'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                       '2d, C), array(float64, 1d, C))',
                                       3,
                                       76,
                                       7.108,
                                       7.108,
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
                                       32,
                                       386.967,
                                       209.956,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.massspring.kernels.spring_forces',
                                       'bench_myriapoda.bodies.massspring.kernels.spring_forces(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                       4,
                                       78,
                                       4.625,
                                       4.625,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                       'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                       'array(float64, 2d, C))',
                                       4,
                                       78,
                                       3.267,
                                       3.267,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                       'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64, float64)',
                                       4,
                                       78,
                                       8.705,
                                       8.705,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                       'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       4,
                                       78,
                                       9.954,
                                       9.954,
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
                                       150.46,
                                       45.646,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                       'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       4,
                                       83,
                                       6.577,
                                       4.991,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._cross',
                                       'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, '
                                       'float64, float64, float64)',
                                       5,
                                       84,
                                       1.586,
                                       1.586,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._step_body',
                                       'bench_myriapoda.bodies.rigid_kernels._step_body(int64, array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'float64, array(float64, 1d, C), int64, array(float64, 1d, C), float64, '
                                       'float64, float64, int64, float64, int64, float64, float64, array(float64, '
                                       '2d, C), array(float64, 2d, C), array(int64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C))',
                                       4,
                                       83,
                                       98.238,
                                       70.419,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, '
                                       '2d, C), float64, float64, float64, array(float64, 2d, C))',
                                       5,
                                       86,
                                       3.537,
                                       3.537,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                       'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       3.046,
                                       3.046,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                       'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                       '2d, C), float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       5,
                                       86,
                                       2.511,
                                       2.511,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64)',
                                       5,
                                       86,
                                       6.336,
                                       6.336,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64)',
                                       5,
                                       86,
                                       3.941,
                                       3.941,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                       'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       5.99,
                                       2.461,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                       'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       6,
                                       92,
                                       3.53,
                                       2.319,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                       'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, '
                                       'float64, float64, float64, float64, float64)',
                                       7,
                                       93,
                                       1.21,
                                       1.21,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                       'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       1.242,
                                       1.242,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                       'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       1.214,
                                       1.214,
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
                                       32,
                                       10.547,
                                       5.51,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, '
                                       '1d, C), float64, array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       2,
                                       97,
                                       5.036,
                                       5.036,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.energy',
                                       'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       0,
                                       None,
                                       3.098,
                                       3.098,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                       'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                       'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       0,
                                       None,
                                       4.465,
                                       4.465,
                                       False,
                                       True)]},
 'massspring-legless-dry': {'args': 'eNqVVFtrE0EUNmkuFkQxYaVaH0LUsoYQqIrPXQsLstQHqeTBlrDZHTtbktmwmUXyIPiUqIwidrz8Df+h58zsbm6bqj00mTnnzHe+c8v70vfflSvq71SaprjN4mHf7XhhRDp8MiLjjtsf88j1uBT1Hmp6EfFCBrrY42EkL6SoeuFoEpEzKa6vG3fWAMeeO3CjMbx7zjg5I8rtaj8OBjxgoK6E/XMC8S7ki5l8J01RYu6QSFEOGH/6BF0D/jbwOZXOgaiMgzNGfPlBlHte6BPp3Iln8qWkW7SSkwwbTdQB0KwocicQhF5LwpR9NKmXtCrK9iB0+YKd3hDVN6gDDvSmc0Drzl0VCvj5wVA6BVEZuJMwhkoVDmXK2nAxjpm8bDf2/Xbj8KFM6R59Kmq+TRQOYQzaSi/6NAPlZSo8GjkXECNVzFWJQZua+bIKs/TmEjhtSo5LWJsvxgYLdmEnq/0uqO85RXqfPqB7azV9pGtKzaPPWTVbCbE8nK0NOI8znC8aB4lYCZilLxZcbBBDcW+pT1sJni39D32yqD2V6DFd7ulKzsZfWmsnKVRF9VkYDojLlkey1AethFms6cSRBPpvL/hUYr05amprH8H5lnbW/JVAeJta0yRii57QE801ldU6GlDHQlLHuq6jipJNOFTxWzGNYyAgiMIRu2t7CT8a3A0YwZ+F8nE8GpClzdQ7a9Lu8pSKshfGjEunCoSQIBHbr1gQsmNc5IU6neNLaAdQVfbXWLV20vdTpPojobonLBXeVB6NbDT+46BS/1nM+rFYR1/NJFaiCZS6m5bPmO/CP5jmvbMA0k+klQ6kGkZowUwqe2uWzXFeT4u5PZ1v2K95YpoQQmE8/LbxU8VTdHIT0N46jVUC3YWhqmkCug/zmfqabibp/AHo1kMm',
                            'case': 'worm/massspring/flat',
                            'events': [('bench_myriapoda.world.terrain_kernels.signed_distance',
                                        'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        0,
                                        None,
                                        20.655,
                                        1.311,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_phi',
                                        'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        1,
                                        0,
                                        11.187,
                                        0.593,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                        'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                        'float64, float64)',
                                        2,
                                        1,
                                        0.404,
                                        0.403,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                        'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        2,
                                        1,
                                        0.709,
                                        0.298,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                        'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                        'C), float64, float64)',
                                        3,
                                        3,
                                        0.411,
                                        0.411,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                        'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        2,
                                        1,
                                        9.481,
                                        0.623,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                        'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        3,
                                        5,
                                        8.858,
                                        1.543,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                        'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, int64)',
                                        4,
                                        6,
                                        7.315,
                                        2.315,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._candidate',
                                        'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        1.704,
                                        1.041,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                        'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                        'float64, float64, float64, float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        6,
                                        8,
                                        0.662,
                                        0.662,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._descend',
                                        'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, float64, float64, float64, '
                                        'int64, int64)',
                                        5,
                                        7,
                                        0.971,
                                        0.971,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                        'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        1.446,
                                        1.446,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                        'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                        'int64, int64, int64)',
                                        5,
                                        7,
                                        0.879,
                                        0.879,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                        'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                        'float64, float64, float64, float64)',
                                        1,
                                        0,
                                        8.157,
                                        0.441,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, '
                                        'C), float64, float64, float64, float64)',
                                        2,
                                        13,
                                        7.716,
                                        0.496,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, '
                                        '1d, C), float64, float64, float64, float64)',
                                        3,
                                        14,
                                        7.22,
                                        5.8,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        4,
                                        15,
                                        0.556,
                                        0.556,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                        '1d, C), float64, float64, float64, float64)',
                                        4,
                                        15,
                                        0.864,
                                        0.864,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                        'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, '
                                        'C), float64, array(float64, 1d, C), float64, float64, int64, array(float64, '
                                        '3d, C))',
                                        0,
                                        None,
                                        0.724,
                                        0.291,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                        'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, '
                                        '2d, C), float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                        1,
                                        18,
                                        0.433,
                                        0.433,
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
                                        40.374,
                                        14.117,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._corner_major',
                                        'bench_myriapoda.bodies.massspring.kernels._corner_major(array(float64, 2d, '
                                        'C), array(float64, 3d, C))',
                                        1,
                                        20,
                                        0.366,
                                        0.366,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._flat_ground',
                                        'bench_myriapoda.bodies.massspring.kernels._flat_ground(int64, '
                                        'array(float64, 1d, C))',
                                        1,
                                        20,
                                        4.829,
                                        1.378,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                        'array(float64, 1d, C), float64, float64, float64)',
                                        2,
                                        22,
                                        3.451,
                                        1.43,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                        'C), int64, float64, float64, float64)',
                                        3,
                                        23,
                                        0.775,
                                        0.775,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_normal',
                                        'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        3,
                                        23,
                                        1.247,
                                        0.639,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                        'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                        'float64, float64)',
                                        4,
                                        25,
                                        0.349,
                                        0.349,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                        'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        4,
                                        25,
                                        0.259,
                                        0.259,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._column_forces_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._column_forces_flat(array(float64, '
                                        '3d, C), int64, bool, array(float64, 1d, C), array(float64, 1d, C), uint64, '
                                        'int64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C))',
                                        1,
                                        20,
                                        10.211,
                                        10.211,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_vectors_c',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_vectors_c(array(float64, '
                                        '3d, C), array(float64, 2d, C))',
                                        1,
                                        20,
                                        0.478,
                                        0.478,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_rows',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_rows(array(float64, 3d, C), '
                                        'int64, array(float64, 1d, C), uint64, uint64)',
                                        1,
                                        20,
                                        0.51,
                                        0.51,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._node_rows',
                                        'bench_myriapoda.bodies.massspring.kernels._node_rows(array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(int64, 1d, C), int64, int64, uint64, uint64, '
                                        'uint64, array(float64, 1d, C), Tuple(bool, float64, float64, float64, '
                                        'float64, float64, float64), array(float64, 1d, C), array(float64, 1d, C))',
                                        1,
                                        20,
                                        6.153,
                                        3.858,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._positions_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._positions_flat(array(float64, '
                                        '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                        'C), array(int64, 1d, C), float64, int64, uint64, uint64, float64, bool, '
                                        'bool, float64, float64, float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        2,
                                        31,
                                        2.295,
                                        2.295,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                        'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64, float64, float64)',
                                        1,
                                        20,
                                        1.614,
                                        1.614,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                        'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        1,
                                        20,
                                        1.852,
                                        1.852,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._node_major',
                                        'bench_myriapoda.bodies.massspring.kernels._node_major(array(float64, 3d, '
                                        'C), array(float64, 2d, C))',
                                        1,
                                        20,
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
                                        1.405,
                                        0.775,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.fibre_stretch',
                                        'bench_myriapoda.bodies.massspring.kernels.fibre_stretch(array(float64, 2d, '
                                        'C), int64, int64)',
                                        1,
                                        36,
                                        0.23,
                                        0.23,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.face_scales',
                                        'bench_myriapoda.bodies.massspring.kernels.face_scales(array(float64, 2d, '
                                        'C), bool, array(float64, 1d, C))',
                                        1,
                                        36,
                                        0.4,
                                        0.4,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_energy',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_energy(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), float64)',
                                        0,
                                        None,
                                        0.797,
                                        0.797,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                        'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C))',
                                        0,
                                        None,
                                        5.474,
                                        0.868,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                        'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                        'array(float64, 2d, C))',
                                        1,
                                        40,
                                        4.606,
                                        1.517,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                        'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                        'float64, float64, float64, float64, float64, float64)',
                                        2,
                                        41,
                                        3.088,
                                        3.088,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                        'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, '
                                        'C), array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), '
                                        'float64, array(bool, 1d, C))',
                                        0,
                                        None,
                                        1.453,
                                        1.453,
                                        False,
                                        True)]}}
