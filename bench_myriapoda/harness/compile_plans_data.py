"""Compile plans recorded by ``python -m bench_myriapoda.harness.compile_plan --record``: generated, do not edit.

The quick matrix's six compile groups, each compiled in a fresh process with an empty numba cache on the 2-core x86-64 development machine (shared with other jobs, load 2-4), numba 0.68.1, Python 3.11, 2026-11-27.  The times say which kernels are large and which depend on which; the signatures are what the cases ask numba for.
"""
NUMBA_VERSION = '0.68.1'
PLANS = {'fem-legged-dry': {'args': 'eNrtGU1vG0XUSWw3kRCglrTFbcDsAbnVKFaTFereMJWQkDEHVKQiVEVre5Nx5OxGm7WKD4alauK0bPnqwAGJY1VF/JVekDjxa5g3H/vhnXXsfHAozijJ7pt5n/Pe25n3/Pyv772bYz/3SaUSvG33dprmastxrVWvv2vtrZrNPc81Wx4JLm0AZMO1Wo5NYb2W57jkGQkutJzdvmttkeD19GSaoL3bZw8kKNRc1+zDqsVmr9P1OjYFFp3mtkXZPSOfDcmAVIJCG5YTvICLwdUUtb2W2TVdIPZx1zEBDb8mEPO2uWNR8TZh4gMduHS8B522h0n9w6Cw0XLaFqlf7w3J54Qubnd2SH0+KHbNvtOj6s7dIZLEsgmCVgQhVF5ro/KdG0TSaAzmGBEQES9J/vgN9v5mcOET27O2LDcmG14OCh0bhMJXqCzFvc6WbbXJIb5aL3FS1+rz+Dpewe8ElzhztjxkjcuNbzKYlijugsAdFXw9xP52DPZcBvatENvn2B5FqWIDBjzq/BFrXpouitFNahRR/U7IVMPGkCIhSqoEw0u+8CdYMQ4Ej0jxQgeSgAgkJvhUST1GySRwxpDjU+IxQSv7BWXMaNTImhxUb7TPVmjRqmg7ONjgaCGFmDpg1AM2W2VkdaxTILxpQ/ivHaiMIaytDUMWFC+532HMlmRc5cO4witZUaWPRNWjyMm4/BqXH7FUcC2VCmjm8cyObbFscLe327Xi2aDAkw7IXGPSOqF3uhUKklbNiOGPHKdrmXYyhvNNCiU0aC/KoJUufpHrBvNxD98XHu6Hg2+ozwQwlENnK4xwPX/W8baMtaDQcnq2R+oIt5i4O8HSF3bHse/CHsQEpnr6bMsAuUa3YjPYZwu/SkuLlLGPlIkQKbMMUm4vUsT+fYJx40CYZvPe3wu5HNu+imItKqtFOEtwwg7/Iew4KddPKvyJLHjr/wxeP8UOZNA+T884sQDHaaafhTG5dDcgyociysVHCj+sF0XSehSlKfwUkvQQckEhn8vxFDXLCLOMMMsIr1ZGGHvISB8RDsMjwqf55BEhg9+Il89SyCyFzFLIK5ZCzmKn2NHkcawi4qSvjfziVc246AL0/djNsNiLyjv45mN6RbycqDPNKe7Db3HZesm6SHgdfiLkOwqvqjU2DPG3Kt41dslD4tcIVxuxm6KG/xg5dP0u74Y1SugIqhX4eXB4hrfDZLpQ1LSQSn3E3mj2f9H4Xuj//N4/8xnZ/zSOnJSlrBRmLPQ8Px5KhpMDJ/s8npjA+ci6NnmekWBB8ESz02Sd8wGHuehFI1DlIh6j8VLdn/T2pAxkWFBlIfzlpCE8QSknsd0sJp/KmAyexANyzHFh7Sy+gWM/pMyAPygN6EL1L1nga6VSd55KehsS9yK+CQX5K5xSuz6PLbyCN2VtD5ZF9Xjc+FGw1EV9Mc5jkEbnNorQfwrRoTqns7vxUvpuXMF/sZrgNuXykpXwHqZ3eG2KJD1tsQ6ltWeH85/l4Tx4OdnJ/PaE26vMEgk9T3fO0o9xJtz4JV6I1lmJvcZqFLyGQT+0B4RX+WVNXNbhs2u3A16hN1JVfijMKl5rymbGSG0fCeY+lWoAY0gYoj8UovviTGDEGGjgbFN1WyIdU/2RqEdQ4mh0IZLoWmxa2w9FMnhhP6EUP8b4bJbrg5iVkbSyFq3mTRAtar9IApqoroM2vlRLNkt4oXyRBs9oq4AGXYkG3wJ15WU5Lf2i/HV5nfnEb9wntvNzuVxks0QnBoB+1LHxRjs1ch7xHg1sVNTe8dnOaIkNxqX90MQa87CYqsB+APbyYofVo6lPiyh+XuStIQlgxKIGUSVqQ1UitDH9s5H+Uxwo5OQcuaMkxdW4ouEjijnwCC3FFPNiGrLSi3WeZb2w92VI3lXZxPSESyHpgNbqv5vqtHo=',
                    'case': 'centipede/fem/walk',
                    'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.69,
                                0.69,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.193,
                                0.193,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                0.313,
                                0.313,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                'array(int64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.293,
                                0.293,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                0,
                                None,
                                15.145,
                                1.274,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_phi',
                                'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                1,
                                4,
                                7.076,
                                0.58,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                'float64)',
                                2,
                                5,
                                0.266,
                                0.266,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                2,
                                5,
                                0.474,
                                0.158,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                'float64, float64)',
                                3,
                                7,
                                0.316,
                                0.315,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                'float64, float64, float64)',
                                2,
                                5,
                                5.756,
                                0.533,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                9,
                                5.222,
                                1.024,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, int64)',
                                4,
                                10,
                                4.199,
                                1.345,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._candidate',
                                'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.992,
                                0.587,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                6,
                                12,
                                0.405,
                                0.405,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._descend',
                                'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.671,
                                0.671,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.768,
                                0.768,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                'int64, int64)',
                                5,
                                11,
                                0.424,
                                0.424,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                1,
                                4,
                                6.794,
                                0.532,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                2,
                                17,
                                6.263,
                                0.575,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, 1d, '
                                'C), float64, float64, float64, float64)',
                                3,
                                18,
                                5.688,
                                4.609,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                4,
                                19,
                                0.486,
                                0.486,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                4,
                                19,
                                0.592,
                                0.592,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                0,
                                None,
                                1.779,
                                0.374,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.side_sign',
                                'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                1,
                                22,
                                0.147,
                                0.147,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, float64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                1,
                                22,
                                1.258,
                                0.411,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_root',
                                'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), array(float64, 1d, C))',
                                2,
                                24,
                                0.668,
                                0.313,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.matvec',
                                'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                25,
                                0.355,
                                0.355,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                'float64, float64)',
                                2,
                                24,
                                0.179,
                                0.179,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, 1d, '
                                'C))',
                                0,
                                None,
                                0.307,
                                0.307,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_poses',
                                'bench_myriapoda.bodies.fem.myriapod.block_poses(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C))',
                                0,
                                None,
                                4.042,
                                0.647,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_centroids',
                                'bench_myriapoda.bodies.fem.myriapod.block_centroids(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C))',
                                1,
                                29,
                                0.297,
                                0.297,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                1,
                                29,
                                3.098,
                                0.491,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                2,
                                31,
                                2.607,
                                2.607,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                'float64, array(float64, 2d, C))',
                                0,
                                None,
                                0.263,
                                0.263,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C), array(float64, 4d, C))',
                                0,
                                None,
                                0.896,
                                0.613,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, 2d, '
                                'C), float64, float64, array(float64, 2d, C))',
                                1,
                                34,
                                0.283,
                                0.283,
                                False,
                                True),
                               ('bench_myriapoda.fused.legged_walk.fem_chunk',
                                'bench_myriapoda.fused.legged_walk.fem_chunk(float64, int64, Tuple(array(float64, '
                                '1d, C), array(int64, 1d, C), Tuple(array(int64, 1d, C), array(float64, 2d, C), '
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
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C)), array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C)), Tuple(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), array(uint64, '
                                '1d, C), array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(int64, 2d, C), array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(bool, 1d, '
                                'C), array(float64, 1d, C), int64, array(float64, 1d, C), int64, array(float64, 1d, '
                                'C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C)), '
                                'Tuple(array(bool, 1d, C), array(int64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 3d, C)), '
                                'Tuple(array(float64, 1d, C), array(int8, 2d, C), array(float64, 3d, C), '
                                'array(int64, 1d, C), array(bool, 2d, C), array(float64, 3d, C), array(float64, 3d, '
                                'C), array(float64, 4d, C), array(float64, 3d, C)))',
                                0,
                                None,
                                75.773,
                                10.622,
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
                                43.458,
                                5.781,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                'int64)',
                                2,
                                37,
                                1.846,
                                1.259,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                'int64, int64)',
                                3,
                                38,
                                0.586,
                                0.586,
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
                                7.661,
                                5.144,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                '1d, C), array(float64, 1d, C), float64, float64)',
                                3,
                                40,
                                0.274,
                                0.274,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                3,
                                40,
                                1.15,
                                0.213,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                'float64, float64, float64, float64, array(int64, 1d, C))',
                                4,
                                42,
                                0.937,
                                0.937,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                'array(int64, 1d, C), int64, float64, float64, float64)',
                                3,
                                40,
                                0.237,
                                0.237,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                40,
                                0.588,
                                0.588,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                '2d, C), float64, float64, float64)',
                                3,
                                40,
                                0.269,
                                0.269,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.tips_touching',
                                'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                2,
                                37,
                                1.098,
                                1.098,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                2,
                                37,
                                0.165,
                                0.165,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, 1d, '
                                'C), int64, array(bool, 1d, C))',
                                2,
                                37,
                                0.32,
                                0.32,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                2,
                                37,
                                7.667,
                                3.021,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                'array(float64, 1d, C), float64, float64, float64)',
                                3,
                                50,
                                2.228,
                                1.015,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_normal',
                                'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                4,
                                51,
                                1.213,
                                0.557,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                'float64)',
                                5,
                                52,
                                0.383,
                                0.383,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                5,
                                52,
                                0.273,
                                0.273,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                'float64, float64, float64)',
                                3,
                                50,
                                1.221,
                                0.552,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                'float64, float64)',
                                4,
                                55,
                                0.331,
                                0.174,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                'float64)',
                                5,
                                56,
                                0.157,
                                0.157,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                '2d, C), int64, float64)',
                                4,
                                55,
                                0.338,
                                0.338,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64)',
                                3,
                                50,
                                0.356,
                                0.356,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, C))',
                                3,
                                50,
                                0.841,
                                0.841,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                'array(float64, 2d, C))',
                                2,
                                37,
                                1.723,
                                1.543,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                61,
                                0.18,
                                0.18,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 1d, C), float64, array(bool, 1d, C))',
                                2,
                                37,
                                2.347,
                                1.211,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                3,
                                63,
                                0.121,
                                0.121,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                3,
                                63,
                                0.154,
                                0.154,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                63,
                                0.286,
                                0.286,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                3,
                                63,
                                0.148,
                                0.148,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, C), '
                                'int64, float64, float64, float64, float64)',
                                3,
                                63,
                                0.426,
                                0.426,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'array(bool, 1d, C))',
                                2,
                                37,
                                5.359,
                                2.598,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'float64, UniTuple(float64 x 3), UniTuple(float64 x 3), float64)',
                                3,
                                69,
                                2.761,
                                1.284,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi',
                                'bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi(int64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, '
                                '1d, C), float64, float64, float64, float64)',
                                4,
                                70,
                                1.477,
                                1.477,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C))',
                                2,
                                37,
                                1.118,
                                0.68,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_tip',
                                'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), float64, float64, float64, float64)',
                                3,
                                72,
                                0.438,
                                0.438,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                2,
                                37,
                                1.752,
                                1.752,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                2,
                                37,
                                5.323,
                                4.316,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                75,
                                0.27,
                                0.27,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs._wrap',
                                'bench_myriapoda.kinematics.legs._wrap(float64)',
                                3,
                                75,
                                0.13,
                                0.13,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs._ik_solve',
                                'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, array(float64, '
                                '2d, C), float64, array(float64, 1d, C), float64)',
                                3,
                                75,
                                0.608,
                                0.608,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'bool, array(bool, 1d, C), array(float64, 1d, C))',
                                2,
                                37,
                                1.298,
                                1.298,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.advance_chain',
                                'bench_myriapoda.bodies.fem.myriapod.advance_chain(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), array(uint64, '
                                '1d, C), array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(int64, 2d, C), array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(bool, 1d, '
                                'C), array(float64, 1d, C), int64, array(float64, 1d, C), int64, array(float64, 1d, '
                                'C), array(float64, 1d, C), int64, array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C))',
                                1,
                                36,
                                20.189,
                                7.053,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                'array(float64, 2d, C))',
                                2,
                                80,
                                9.095,
                                0.608,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 2d, C))',
                                3,
                                81,
                                0.356,
                                0.356,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                3,
                                81,
                                4.069,
                                4.069,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                3,
                                81,
                                3.621,
                                1.999,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                4,
                                84,
                                1.622,
                                1.163,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                5,
                                85,
                                0.458,
                                0.458,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), array(uint64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                3,
                                81,
                                0.441,
                                0.441,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                2,
                                80,
                                2.185,
                                0.74,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                3,
                                88,
                                1.445,
                                1.444,
                                False,
                                True),
                               ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64, float64)',
                                2,
                                80,
                                0.949,
                                0.949,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                2,
                                80,
                                0.907,
                                0.907,
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
                                1.504,
                                0.92,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, C), '
                                'float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                'array(float64, 4d, C))',
                                2,
                                92,
                                0.584,
                                0.584,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                0.766,
                                0.766,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.757,
                                0.757,
                                False,
                                True),
                               ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), int64, '
                                'int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                0,
                                None,
                                1.093,
                                1.093,
                                False,
                                True)]},
 'fem-legless-dry': {'args': 'eNqNVFuL00AUtrttVkFUdl1d466UPEiVoUUNQt+sC4KE9cF3KZNk7GRpk5JOkD4IPlmFeXJHvIH+VeeWyaVNtQPpucz5zjdzzpkP7a9frEvy94b1evROnM182A+SFPXJco4WfegvSAoDwujBWFjGKQqSmNuygCQpu2B0L0jmyxRNGL227lwHjOdLKTDaGaUpXIpdl/0smpIo5kYr8c8RT3fBXq3Ye9ajnVBsZ3gXW/RoDW0RwClMBdiLaQJFGL6qA9sxnCFO761wPHVFloi8i0KCmfeMdsZBEiLmHWcr9prxzWE0Y94OtaZwmWT8uK1TlkMcQkG0p4FA93EIuqcPWI5x9q0lQQRFfCXPj69L/QbdexkTNEFpiRs+pJ0oFqTwbc7FWkSTGIXsEz7ybAV119vBx/gE36MHKrncblLj7tn3hqQ2j93VsXXiT0z0jy3RrYboRyb6p4omPGSAh2IJ0VUidsg6LijhVk9UoP7SnEZ4uOJBgEPZYpGqoiSxY5tJiGCDwhfIDYVJO5TL3rzqMJWYLXDKpcUKVrMCGjwOF4Ya3C0bHKU4XBmYQozk1+X/IynXv0BmGsqvK6PFqpSuPH74fql/raxoYPzwM+/cW5VJaplJwif5HN1Uhc+qlTdj9FvXHxkqTrWx1HnEkfVkPU+SKYJxdbLaPrcyTmhfwbn55QwMKhI5ODNpW+mbc9Q+UFbsbc3w/0akzqRoqBNUayJdJdGRimHU1NXgHyMAiu6pU9rgKlrIzi/MLaY7V02naYaqc+RlOh8NdQVffwVmpVdgXzWDKFb5EfiTPy2o/xeNYSwC',
                     'case': 'worm/fem/flat',
                     'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                 'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.425,
                                 0.425,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                 'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.119,
                                 0.119,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                 'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 0.306,
                                 0.306,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.185,
                                 0.185,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                 'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                 'C), float64, float64, float64)',
                                 0,
                                 None,
                                 10.002,
                                 0.609,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_phi',
                                 'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 1,
                                 4,
                                 4.984,
                                 0.383,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                 'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                 'float64)',
                                 2,
                                 5,
                                 0.156,
                                 0.156,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                 'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 2,
                                 5,
                                 0.324,
                                 0.104,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                 'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                 'float64, float64)',
                                 3,
                                 7,
                                 0.221,
                                 0.221,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                 'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 5,
                                 4.12,
                                 0.392,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                 'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 3,
                                 9,
                                 3.728,
                                 0.935,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                 'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, int64)',
                                 4,
                                 10,
                                 2.793,
                                 1.107,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._candidate',
                                 'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 0.578,
                                 0.335,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                 'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 6,
                                 12,
                                 0.243,
                                 0.243,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._descend',
                                 'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                 'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                 5,
                                 11,
                                 0.402,
                                 0.402,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                 'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                 'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                 'int64)',
                                 5,
                                 11,
                                 0.461,
                                 0.461,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                 'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                 'int64, int64)',
                                 5,
                                 11,
                                 0.245,
                                 0.245,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                 'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 1,
                                 4,
                                 4.408,
                                 0.295,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 2,
                                 17,
                                 4.114,
                                 0.341,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, 1d, '
                                 'C), float64, float64, float64, float64)',
                                 3,
                                 18,
                                 3.773,
                                 2.941,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                 'float64, float64, float64)',
                                 4,
                                 19,
                                 0.299,
                                 0.299,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                 'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                 'float64, float64, float64, float64)',
                                 4,
                                 19,
                                 0.533,
                                 0.533,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                 'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, float64, int64, array(float64, 3d, C))',
                                 0,
                                 None,
                                 0.427,
                                 0.176,
                                 False,
                                 True),
                                ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                 'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, 2d, C), '
                                 'float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                 1,
                                 22,
                                 0.251,
                                 0.251,
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
                                 30.453,
                                 6.121,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                 'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, C), '
                                 'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                 'float64, bool, array(float64, 3d, C), array(float64, 2d, C))',
                                 1,
                                 24,
                                 1.029,
                                 1.029,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 24,
                                 13.372,
                                 0.635,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                 'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                 '2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 0.744,
                                 0.744,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 6.332,
                                 6.332,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                 'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 5.049,
                                 2.489,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                 'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64)',
                                 3,
                                 29,
                                 2.56,
                                 0.967,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                 'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                 'float64, float64, float64, float64, float64)',
                                 4,
                                 30,
                                 1.351,
                                 1.351,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                 'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                 'float64, float64, float64, float64, float64, float64)',
                                 4,
                                 30,
                                 0.242,
                                 0.242,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                 'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), '
                                 'array(uint64, 1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                 2,
                                 26,
                                 0.612,
                                 0.612,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                 'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                 'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                 'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 1,
                                 24,
                                 3.831,
                                 1.102,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                 'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                 '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                 2,
                                 34,
                                 2.729,
                                 2.729,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.segment_spines',
                                 'bench_myriapoda.bodies.fem.body_kernels.segment_spines(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                 '2d, C))',
                                 1,
                                 24,
                                 0.749,
                                 0.749,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                 'array(float64, 1d, C), float64, float64, float64)',
                                 1,
                                 24,
                                 3.752,
                                 1.017,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                 'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                 'int64, float64, float64, float64)',
                                 2,
                                 37,
                                 1.32,
                                 1.32,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._other_normal',
                                 'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                 'float64, float64, float64)',
                                 2,
                                 37,
                                 1.415,
                                 0.803,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                 'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                 'float64)',
                                 3,
                                 39,
                                 0.343,
                                 0.343,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                 'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                 'float64, float64)',
                                 3,
                                 39,
                                 0.269,
                                 0.269,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                 'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                 'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                 'float64, float64)',
                                 1,
                                 24,
                                 0.717,
                                 0.717,
                                 False,
                                 True),
                                ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                 'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                 '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                 1,
                                 24,
                                 0.883,
                                 0.883,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity',
                                 'bench_myriapoda.bodies.fem.body_kernels.kinetic_and_gravity(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(float64, 1d, C), float64)',
                                 0,
                                 None,
                                 0.203,
                                 0.203,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                 'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '1d, C), array(float64, 1d, C))',
                                 0,
                                 None,
                                 0.614,
                                 0.614,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                 'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                 'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                 '2d, C))',
                                 0,
                                 None,
                                 0.547,
                                 0.547,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                 'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, C), '
                                 'array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, '
                                 '2d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 0,
                                 None,
                                 0.9,
                                 0.564,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                 'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                 'array(float64, 2d, C))',
                                 1,
                                 47,
                                 0.336,
                                 0.336,
                                 False,
                                 True),
                                ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                 'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, C), '
                                 'array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), float64, '
                                 'array(bool, 1d, C))',
                                 0,
                                 None,
                                 0.827,
                                 0.827,
                                 False,
                                 True)]},
 'hybrid-legged-dry': {'args': 'eNrtGktv40Q4bZNsKyFALWWX7BZFPqyyq1GrNhaqLwiz0koohANaJF6ryk3cTqrUrlJHkEMka0UbkMxpzY0DsCCgvN+q9i9w5MaFn8K8PY7HaZqmi3ZJrbb2zHzffI/5Pn8P+9mPOlcz5Od2WCoFzzjt3U1ruea27GWvs2fvL1ub+17LqnlhsLCBRzZads110Fi75rmt8G4YXKi5e52WvR0GjycnkwidvQ65CYOc2WpZHbxqdrPdaHoNBw3m3c0dG213N3ylF3bDUpCr4+UhnIH54FIC237NalotjOxm07UwGHyMAWYda9dG5G3hied0vEvDe6dR92BYeSHIbdTcuh1WrrR74ashWlxv7IaV6SDftDpuG7E7dSPkKBYtTGiJIQLFtToo3rgWchzVT6YIEkwinOP7wyfI85PBhZccz962WxJtcDHINRxMFLyIaMnvN7Ydux6+Dy9VChTV5co0vAKX4LPBAt2cLBdbw2L105RNCwh2hsH2E14W0J8NgJ5KgV4V0PcotIdAVqCBL3yr01uoeUm8QMIb5yjC+jmjyYRGL8R4oNZDwADdFvDlxR/oHV4xaAjfAsUDugAfiIbYBJ0qqK9+NDGYAejoFLuN4Up/ACkzJro0censP9ICfjqUaNfw6miFRpQDDgg+LcIZKZEOGxRM7Ccxj1VwSCWt9QSAjq6YzoXdFrhtZYVtwaU0y9L7LOvL6KBpET9YpNgdXE64A+R9PKvh2MQj3GrvNW3ZI+So48E0m4RaV5zQVkmSaIodv+i6Tdty4nac3USjITLceW64/JjPU97wvHzKv2Kn3BcXVY9PCDCUl05WGGI9vdfhDre3IFdz244XVgCsEXJ3g7nXnIbr3MI6kAhGfPpEZRjYRKrYCg7IwreS1AKl/QOlMwRKTwOU6gUK+78dQlj9molm6/W/ZjIZor6SYi0oqkkY53BMDg9w7CQqy6MSP5IEV//Pw+UzaCAF93mejJEJOIkzfRzCpNRdw1Z+xKycvXLgnUqeOa33IjcFP8ROuod9QS6byVAXNfEIE48w8QiPlkcYGGQkQ4RvRIjwcjYeIqTs13fKJy5k4kImLuQRcyHj0BQJTb6VqiKx3BCnXCskCYtNRRklr32YNF+TMrJZuYIlhTgfk7wOhTg8F74p52EnJF3lAV5SJM/fMW7uBfeVjrI8/nM+2CGMYipIL19UvxchoyJBj8n3qpSa59tRjQ1e/wDl6E/Hin1TioLEU5SIdrw4JUT6AyPkmFRgTKJw/pf/j+oylFyfHA7Afo3EPK/OmCTN11lBRWOx8fPJ2LgEj0QSb6JjeYyLSuiN+OaUKlB+yNQNzrEOESdXUVcFKu0D8kSijx9F9JHJp0QfQznS+KanfBk8zMo9lWMfbbitpFs9esbB0wjufBCcM1lrD354dczx9bAWwgQx0uz5H+r/QJhjSRoG+7+xxMjlcbA+ymoSMf6UFjH6JF6k7/Cs6h3uk/hvhZTg3zhbCb6c+kIjb62f+VsreFt+dwxI6NZGEDURxy9p4jD6miq1RLSWRXuv41htFl7HjdCLFFO9Mg1tuISInxckrkd9UFj9lW2ps56OvEc3CU65jsB/E+C4I6ITfc2p9PUP0dcO2uVvorM7SZ2tjaqzIRokIMk9Ue7vQrl/DlcNWR9SvUobjfF5NgPVT4j6YfUPufmnkyalSerCtG6M4mnShwQQ8D4k72Sm98u6tMdpJLqquBmmeDSVzeO+7ihgm/uIqi6+eiEB9HuMdJ+F/oa0gYYP26m62xGPiX501J0tUDC0EHBwTZrWDgRJBm2mxpgySb7ik1nKDyBSBlzKWrSatpG1qN3NEfCUBnPjc7Z4u5k2J2eR8fS3Z5HRFZDxzaCjvMin+bkovlsskzNxn56JnQWU60Qyi/Wy8aAf9by9/l43nwe0y40VFTXIfaIZLaZgWDgQItbICZNYxdt3sbwoCOfe50eWtOSNw1CuIRyJzO/4TJkkOE0u2V+jwJx08XJC4Qpt5muRzID8UBj0McTwgxrbN86yxr9oMBgx2qFsC0k0iqnkRxGalGr3i4+n4QOEZcpfTJSSFCQ3oR4qog2w30L6Jlr0lQY33BI7ZCeLdHjRR1QPq0O1TyH+l7skys4OZWOFcibbAGNUnhfflQAmJuQd7OV/AQCp4Z4=',
                       'case': 'centipede/hybrid/walk',
                       'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                   'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   1.088,
                                   1.088,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                   'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.799,
                                   0.799,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                   'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.645,
                                   1.645,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   1.434,
                                   1.434,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.593,
                                   1.593,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                   'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   0,
                                   None,
                                   33.859,
                                   0.521,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_phi',
                                   'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   1,
                                   5,
                                   21.053,
                                   0.551,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                   'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                   'float64)',
                                   2,
                                   6,
                                   0.979,
                                   0.979,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                   'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   2,
                                   6,
                                   2.224,
                                   0.74,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                   'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                   'float64, float64)',
                                   3,
                                   8,
                                   1.484,
                                   1.484,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                   'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   2,
                                   6,
                                   17.299,
                                   0.512,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                   'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                   'float64, float64, float64)',
                                   3,
                                   10,
                                   16.787,
                                   1.741,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                   'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, int64)',
                                   4,
                                   11,
                                   15.045,
                                   2.358,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._candidate',
                                   'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   5.118,
                                   3.022,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                   'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   6,
                                   13,
                                   2.096,
                                   2.096,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._descend',
                                   'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                   5,
                                   12,
                                   3.6,
                                   3.6,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                   'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   3.5,
                                   3.5,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                   'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                   'int64, int64, int64)',
                                   5,
                                   12,
                                   0.469,
                                   0.469,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                   'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   1,
                                   5,
                                   12.286,
                                   0.53,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   2,
                                   18,
                                   11.755,
                                   0.998,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   3,
                                   19,
                                   10.757,
                                   6.855,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   4,
                                   20,
                                   1.597,
                                   1.597,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   4,
                                   20,
                                   2.304,
                                   2.304,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.hybrid.kernels.place_attached_nodes',
                                   'bench_myriapoda.bodies.hybrid.kernels.place_attached_nodes(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.696,
                                   0.396,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                   'array(float64, 3d, C))',
                                   1,
                                   23,
                                   0.3,
                                   0.104,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, float64, '
                                   'float64, array(float64, 2d, C))',
                                   2,
                                   24,
                                   0.196,
                                   0.196,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.856,
                                   0.217,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.side_sign',
                                   'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                   1,
                                   26,
                                   0.044,
                                   0.044,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                   'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   1,
                                   26,
                                   0.594,
                                   0.253,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_root',
                                   'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   2,
                                   28,
                                   0.253,
                                   0.135,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.matvec',
                                   'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   29,
                                   0.118,
                                   0.118,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                   'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   28,
                                   0.088,
                                   0.088,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                   'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, '
                                   '1d, C))',
                                   0,
                                   None,
                                   0.153,
                                   0.153,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                   'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                   'float64, array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.124,
                                   0.124,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 4d, C))',
                                   0,
                                   None,
                                   0.59,
                                   0.408,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                   'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                   '2d, C), float64, float64, array(float64, 2d, C))',
                                   1,
                                   34,
                                   0.182,
                                   0.182,
                                   False,
                                   True),
                                  ('bench_myriapoda.fused.legged_walk.hybrid_chunk',
                                   'bench_myriapoda.fused.legged_walk.hybrid_chunk(float64, int64, '
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
                                   'Tuple(array(float64, 2d, C), array(float64, 2d, C), array(int64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), Tuple(array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 3d, C)), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(uint64, 1d, C), '
                                   'array(uint64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                   'C), array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                   'array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), array(int64, '
                                   '1d, C), array(float64, 1d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), array(float64, '
                                   '3d, C), array(float64, 1d, C), int64, array(float64, 1d, C), int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                   'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C)), Tuple(array(bool, 1d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C)), '
                                   'Tuple(array(float64, 1d, C), array(int8, 2d, C), array(float64, 3d, C), '
                                   'array(int64, 1d, C), array(bool, 2d, C), array(float64, 3d, C), array(float64, '
                                   '3d, C), array(float64, 4d, C), array(float64, 3d, C)))',
                                   0,
                                   None,
                                   133.822,
                                   24.289,
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
                                   46.044,
                                   4.582,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                   'int64)',
                                   2,
                                   37,
                                   1.68,
                                   1.18,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                   'int64, int64)',
                                   3,
                                   38,
                                   0.499,
                                   0.499,
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
                                   13.12,
                                   10.414,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                   'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                   '1d, C), array(float64, 1d, C), float64, float64)',
                                   3,
                                   40,
                                   0.273,
                                   0.273,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                   'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                   'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                   3,
                                   40,
                                   1.327,
                                   0.15,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                   'float64, float64, float64, float64, array(int64, 1d, C))',
                                   4,
                                   42,
                                   1.177,
                                   1.177,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                   'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                   'array(int64, 1d, C), int64, float64, float64, float64)',
                                   3,
                                   40,
                                   0.3,
                                   0.3,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   40,
                                   0.503,
                                   0.503,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                   'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                   '2d, C), float64, float64, float64)',
                                   3,
                                   40,
                                   0.303,
                                   0.303,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.tips_touching',
                                   'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                   2,
                                   37,
                                   1.22,
                                   1.22,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                   'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                   2,
                                   37,
                                   0.146,
                                   0.146,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                   'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                   '1d, C), int64, array(bool, 1d, C))',
                                   2,
                                   37,
                                   0.384,
                                   0.384,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                   'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, '
                                   'C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                   2,
                                   37,
                                   7.053,
                                   2.712,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                   'array(float64, 1d, C), float64, float64, float64)',
                                   3,
                                   50,
                                   2.434,
                                   1.163,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_normal',
                                   'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   4,
                                   51,
                                   1.271,
                                   0.629,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                   'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                   'float64, float64)',
                                   5,
                                   52,
                                   0.37,
                                   0.37,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                   'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   5,
                                   52,
                                   0.272,
                                   0.272,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                   'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64, float64)',
                                   3,
                                   50,
                                   1.038,
                                   0.532,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                   'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                   'float64, float64)',
                                   4,
                                   55,
                                   0.261,
                                   0.125,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                   'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                   'float64)',
                                   5,
                                   56,
                                   0.136,
                                   0.136,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                   'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                   '2d, C), int64, float64)',
                                   4,
                                   55,
                                   0.244,
                                   0.244,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                   'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64)',
                                   3,
                                   50,
                                   0.225,
                                   0.225,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                   'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, '
                                   'C))',
                                   3,
                                   50,
                                   0.645,
                                   0.645,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                   'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                   '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   37,
                                   1.965,
                                   1.776,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   61,
                                   0.189,
                                   0.189,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                   'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                   'C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   2,
                                   37,
                                   2.187,
                                   1.183,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                   'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                   3,
                                   63,
                                   0.106,
                                   0.106,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                   'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                   3,
                                   63,
                                   0.139,
                                   0.139,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                   'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   63,
                                   0.268,
                                   0.268,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                   'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                   3,
                                   63,
                                   0.152,
                                   0.152,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                   'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, '
                                   'C), int64, float64, float64, float64, float64)',
                                   3,
                                   63,
                                   0.339,
                                   0.339,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(bool, 1d, C))',
                                   2,
                                   37,
                                   5.011,
                                   2.049,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3), '
                                   'float64)',
                                   3,
                                   69,
                                   2.962,
                                   1.187,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, float64, float64, float64)',
                                   4,
                                   70,
                                   1.775,
                                   1.775,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                   'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   37,
                                   0.74,
                                   0.415,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_tip',
                                   'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), float64, float64, float64, float64)',
                                   3,
                                   72,
                                   0.326,
                                   0.326,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                   '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                   2,
                                   37,
                                   1.254,
                                   1.254,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                   'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   37,
                                   4.577,
                                   3.877,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                   'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   75,
                                   0.25,
                                   0.25,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._wrap',
                                   'bench_myriapoda.kinematics.legs._wrap(float64)',
                                   3,
                                   75,
                                   0.058,
                                   0.058,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._ik_solve',
                                   'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                   'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                   3,
                                   75,
                                   0.393,
                                   0.393,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, '
                                   'C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                   2,
                                   37,
                                   2.124,
                                   2.124,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                   'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                   '3d, C), float64, array(float64, 1d, C))',
                                   1,
                                   36,
                                   2.167,
                                   0.884,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                   'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, 2d, '
                                   'C), array(float64, 1d, C))',
                                   2,
                                   80,
                                   1.283,
                                   1.283,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.hybrid.kernels.advance',
                                   'bench_myriapoda.bodies.hybrid.kernels.advance(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(int64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), Tuple(array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C)), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                   '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), array(bool, '
                                   '1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, array(float64, 1d, '
                                   'C), int64, array(float64, 1d, C), array(float64, 1d, C), int64, array(float64, '
                                   '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                   'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C))',
                                   1,
                                   36,
                                   59.085,
                                   13.544,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                   'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, '
                                   'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, bool, array(float64, 3d, C), array(float64, 2d, '
                                   'C))',
                                   2,
                                   82,
                                   0.955,
                                   0.955,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                   'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   82,
                                   0.784,
                                   0.784,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   82,
                                   7.662,
                                   7.662,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   82,
                                   5.19,
                                   2.747,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                   'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   3,
                                   86,
                                   2.443,
                                   1.09,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                   'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   4,
                                   87,
                                   1.116,
                                   1.116,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                   'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   4,
                                   87,
                                   0.237,
                                   0.237,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                   'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   2,
                                   82,
                                   3.932,
                                   1.063,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   3,
                                   90,
                                   2.869,
                                   2.868,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.hybrid.kernels.link_spines',
                                   'bench_myriapoda.bodies.hybrid.kernels.link_spines(array(float64, 2d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   82,
                                   0.568,
                                   0.568,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                   'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                   '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   82,
                                   1.69,
                                   1.69,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                   'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                   'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   82,
                                   1.528,
                                   1.528,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.hybrid.kernels.rigid_segments_step',
                                   'bench_myriapoda.bodies.hybrid.kernels.rigid_segments_step(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), array(bool, '
                                   '1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, array(float64, 1d, '
                                   'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(int64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C))',
                                   2,
                                   82,
                                   23.232,
                                   10.266,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                   'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   3,
                                   95,
                                   0.978,
                                   0.813,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._cross',
                                   'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   96,
                                   0.165,
                                   0.165,
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
                                   95,
                                   11.987,
                                   8.463,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                   'C), float64, float64, float64, array(float64, 2d, C))',
                                   4,
                                   98,
                                   0.285,
                                   0.285,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                   'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                   4,
                                   98,
                                   0.215,
                                   0.215,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                   'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, 2d, '
                                   'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   4,
                                   98,
                                   0.225,
                                   0.225,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   4,
                                   98,
                                   0.417,
                                   0.417,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64)',
                                   4,
                                   98,
                                   0.523,
                                   0.523,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                   'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64)',
                                   4,
                                   98,
                                   1.446,
                                   0.432,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                   'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   104,
                                   1.015,
                                   0.718,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                   'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                   'float64, float64, float64, float64)',
                                   6,
                                   105,
                                   0.297,
                                   0.297,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                   'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                   'float64)',
                                   4,
                                   98,
                                   0.236,
                                   0.236,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                   'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                   4,
                                   98,
                                   0.178,
                                   0.178,
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
                                   2.238,
                                   1.341,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, '
                                   'C), float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, '
                                   'C), array(float64, 4d, C))',
                                   2,
                                   109,
                                   0.897,
                                   0.897,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                   'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.704,
                                   1.704,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.energy',
                                   'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.8,
                                   0.8,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                   'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.917,
                                   0.917,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                   'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                   'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   0,
                                   None,
                                   1.077,
                                   1.077,
                                   False,
                                   True)]},
 'hybrid-legless-dry': {'args': 'eNqlVF1r01AYttvabSAqm9OZbVJyIVVCixqE3FkHAynzQuaFyBxpetYT6ZKSJkgvBl61Ds7djr/GT/DjH3nv+UzOadI4tIcm57yfT97zvs+7pQ+/Vy+x3yFuNNCtIDnpuk0vjEAzHg/BqOl2R3HkejFG60dUchQBLwyILPHiMMLnGC174XAcgT5GV/LKfMBgOGYbjKrtKHLH1Gqlm/iD2A+IsBZ23wCS7hw/m+JT3EDVHjXHcBHW0GYu2shzB25Eg+0NQpe6wcvCcSlwTwCBd0wVj2yaxY/f+r0Y4s5jVD3ywh7Ane1kip9jYtzzT3BnAdUG7jhMyOdWdrEMseFSoA0RyKo/6Fn13btYxtj/VGFBKES4KvPDq+x8DS0/DWLQB5GCDW6gqh9QUPAmwVIb+f0A9PB7uNkxeKitzgLchjvwNlrnyZl5mhrW9z/PSWoQ30XhOwv8Yer9pcS7Msf7fur9lXvHxKUFHbro1uZbaMb5uJYSV/+iLOo3gakNnSmmcaA5Jc4W2Rp0xfqB76hFmYhurYIDWZYUZCKh4CqjeM2G0XxKwnGV2Gqx5h+sOZo2WWa6bPEmt0BPEwW7Sa2prsWs6BBt5YaIzGzs+gFgc3SQDAdAnaMqH9fsftvsaZMZqXphEsS4s6JOKXyJVl8EfhgcUInS9K+pF2xP07naY2avCtvMKmxdq6B1DrNB/C46qI8+ss9oFAepF2f8J7EG5T8jc3hkFvz9H+JLHHG12jxp1b6jkEotyVgF3jsjdHJDo7dKSm9wR17CdQ4i0ccxLelPAeSU9VybXb98ynfWiU4ebMaDT8JwANxA58GlLpFignRNEp+kiTUOjOpVlvglANlsPPifPmdByLFok7fNrLlGoyreyiYZlAk1Z/PT4rQjonHSUQ5GGS9cXGiKvHpVTTncjgBjTmYZUCMF6y/cZ2W0MQugQJVnlqyYcneWFt4RkpIyK6FmCqGVVUliE6WjYLPE35ifxNSpTpbDkOUwUovyeym5qvn67Fsu2hOKSEXJGdrJCFvWJRW1ZNfyoyWqdKY62OR+RBFZ+zgToXTSu3CYAQsDmn8AjRQ8EA==',
                        'case': 'chain/hybrid/fig4-drop',
                        'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                    'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.016,
                                    1.016,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                    'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.29,
                                    0.29,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                    'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.535,
                                    0.535,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.43,
                                    0.43,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.517,
                                    0.517,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                    'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    0,
                                    None,
                                    12.948,
                                    0.899,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_phi',
                                    'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    1,
                                    5,
                                    6.539,
                                    0.381,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                    'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                    'float64)',
                                    2,
                                    6,
                                    0.364,
                                    0.363,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                    'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                    'float64, float64)',
                                    2,
                                    6,
                                    0.544,
                                    0.165,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                    'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                    'float64, float64)',
                                    3,
                                    8,
                                    0.379,
                                    0.379,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                    'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    2,
                                    6,
                                    5.25,
                                    0.352,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                    'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                    'float64, float64, float64)',
                                    3,
                                    10,
                                    4.899,
                                    0.864,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                    'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, int64)',
                                    4,
                                    11,
                                    4.035,
                                    1.317,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._candidate',
                                    'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    0.94,
                                    0.533,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                    'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    6,
                                    13,
                                    0.407,
                                    0.407,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._descend',
                                    'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                    'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                    5,
                                    12,
                                    0.646,
                                    0.646,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                    'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                    'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                    'int64)',
                                    5,
                                    12,
                                    0.74,
                                    0.74,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                    'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                    'int64, int64, int64)',
                                    5,
                                    12,
                                    0.392,
                                    0.392,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                    'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                    'float64, float64, float64, float64)',
                                    1,
                                    5,
                                    5.511,
                                    0.417,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                    'float64, float64, float64, float64)',
                                    2,
                                    18,
                                    5.093,
                                    0.419,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, '
                                    '1d, C), float64, float64, float64, float64)',
                                    3,
                                    19,
                                    4.674,
                                    3.776,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    4,
                                    20,
                                    0.285,
                                    0.285,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                    'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                    'C), float64, float64, float64, float64)',
                                    4,
                                    20,
                                    0.613,
                                    0.613,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.hybrid.kernels.place_attached_nodes',
                                    'bench_myriapoda.bodies.hybrid.kernels.place_attached_nodes(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.303,
                                    0.724,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                    'array(float64, 3d, C))',
                                    1,
                                    23,
                                    0.58,
                                    0.243,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                    'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                    'float64, float64, array(float64, 2d, C))',
                                    2,
                                    24,
                                    0.337,
                                    0.337,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.hybrid.kernels.advance',
                                    'bench_myriapoda.bodies.hybrid.kernels.advance(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(int64, 2d, C), array(float64, 3d, C), '
                                    'array(float64, 2d, C), Tuple(array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 3d, C)), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), array(float64, '
                                    '2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(bool, 1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, '
                                    'array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, 1d, C), '
                                    'int64, array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(int64, 1d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                    'array(float64, 3d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    54.973,
                                    9.602,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.body_kernels.active_coefficients',
                                    'bench_myriapoda.bodies.fem.body_kernels.active_coefficients(array(float64, 3d, '
                                    'C), array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), float64, bool, array(float64, 3d, C), array(float64, 2d, '
                                    'C))',
                                    1,
                                    26,
                                    0.563,
                                    0.563,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                    'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 2d, C))',
                                    1,
                                    26,
                                    0.392,
                                    0.392,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    1,
                                    26,
                                    4.285,
                                    4.285,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                    'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                    1,
                                    26,
                                    6.677,
                                    2.676,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                    'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    2,
                                    30,
                                    4.002,
                                    2.021,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                    'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    3,
                                    31,
                                    1.633,
                                    1.633,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                    'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    3,
                                    31,
                                    0.347,
                                    0.347,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                    'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, '
                                    'C), array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                    '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    1,
                                    26,
                                    3.598,
                                    0.695,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                    'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                    2,
                                    34,
                                    2.903,
                                    2.902,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.hybrid.kernels.link_spines',
                                    'bench_myriapoda.bodies.hybrid.kernels.link_spines(array(float64, 2d, C), '
                                    'array(float64, 2d, C))',
                                    1,
                                    26,
                                    0.336,
                                    0.336,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                    'array(float64, 1d, C), float64, float64, float64)',
                                    1,
                                    26,
                                    3.158,
                                    1.08,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                    'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                    'int64, float64, float64, float64)',
                                    2,
                                    37,
                                    0.91,
                                    0.91,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._other_normal',
                                    'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                    'C), float64, float64, float64)',
                                    2,
                                    37,
                                    1.167,
                                    0.693,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                    'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                    'float64, float64)',
                                    3,
                                    39,
                                    0.265,
                                    0.265,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                    'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                    'float64, float64, float64)',
                                    3,
                                    39,
                                    0.209,
                                    0.209,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                    'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                    '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    1,
                                    26,
                                    0.58,
                                    0.58,
                                    False,
                                    True),
                                   ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                    'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                    'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                    'float64, float64)',
                                    1,
                                    26,
                                    0.756,
                                    0.756,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.hybrid.kernels.rigid_segments_step',
                                    'bench_myriapoda.bodies.hybrid.kernels.rigid_segments_step(array(int64, 1d, C), '
                                    'array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(bool, 1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, '
                                    'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                    'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C), array(float64, 1d, C))',
                                    1,
                                    26,
                                    25.026,
                                    4.35,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                    'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C))',
                                    2,
                                    44,
                                    0.723,
                                    0.616,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._cross',
                                    'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                    'float64, float64)',
                                    3,
                                    45,
                                    0.107,
                                    0.107,
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
                                    2,
                                    44,
                                    19.952,
                                    12.762,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                    'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                    'C), float64, float64, float64, array(float64, 2d, C))',
                                    3,
                                    47,
                                    1.021,
                                    1.021,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.matvec',
                                    'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    3,
                                    47,
                                    1.197,
                                    1.197,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                    'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                    3,
                                    47,
                                    0.678,
                                    0.678,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                    'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                    '2d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    3,
                                    47,
                                    0.664,
                                    0.664,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                    'float64, float64, float64, float64, float64, float64)',
                                    3,
                                    47,
                                    1.457,
                                    1.457,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                    'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    3,
                                    47,
                                    1.051,
                                    1.051,
                                    False,
                                    True),
                                   ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                    'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                    'float64, float64)',
                                    3,
                                    47,
                                    0.155,
                                    0.155,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                    'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64)',
                                    3,
                                    47,
                                    0.687,
                                    0.203,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                    'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                    'float64, float64, float64, float64, float64, float64, float64, float64, '
                                    'float64)',
                                    4,
                                    55,
                                    0.484,
                                    0.297,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                    'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                    'float64, float64, float64, float64)',
                                    5,
                                    56,
                                    0.187,
                                    0.187,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                    'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                    'float64)',
                                    3,
                                    47,
                                    0.069,
                                    0.069,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                    'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                    3,
                                    47,
                                    0.212,
                                    0.212,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                    'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.606,
                                    0.606,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.rigid_kernels.energy',
                                    'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                    'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                    'array(float64, 2d, C))',
                                    0,
                                    None,
                                    0.374,
                                    0.373,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                    'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                    'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                    'array(float64, 1d, C), array(float64, 1d, C))',
                                    0,
                                    None,
                                    0.378,
                                    0.378,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                    'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                    'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                    0,
                                    None,
                                    0.499,
                                    0.499,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                    'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                    'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                    'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                    0,
                                    None,
                                    1.641,
                                    1.198,
                                    False,
                                    True),
                                   ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                    'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                    '2d, C), array(float64, 1d, C))',
                                    1,
                                    64,
                                    0.443,
                                    0.443,
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
                                    8.679,
                                    8.679,
                                    False,
                                    True)]},
 'massspring-legged-dry': {'args': 'eNrtWd1vG0UQTxo7TSREUauoxW2RdS/nolO4xBHqI1AJC9nhARWptLWis33JGjl3kXPWYSEkhEgM0r2gLnlD/Bc88cIjiG/KNzzwP/AHdHd293bPt+e4jlOJ4qwinfdjdmZ+M7O7M+/mPv6sOAd/dVyKnvZ6uw1ntel33dWgv+furzqN/aDrNAMcXdiiPVtdt+l7pK/XDPwuvoejs01/r991d3D0ZHowTdDb68MHjvIvdrtOn85aavTanaDtkc5Fv/GmS7a7h18d4HcIS/kWnY7RAlqMLqWo7TedjtOlxF7u+A5dhp7gC3Oes+sS9rbpwPMbdJd2ELZbAcLVF6L8VtNvubh6pTfAr2EyudXexdX5aLHj9P0eEXf+BhYkVhzKaIkTsoprLat44xoWNDa/nAcilEW0LPZH51ABXa6eQVfQVfRMisY6o4GKm1/x1eaALKIknorOvuIF7o7bVcRBK1G+7VE50EXC/uJ+e8dzW/gDdKlaYOsNsh9pAZlryx/si5Ie1UU/bc0P0mzRIbv4ABsq6NswmcSaEeTYEP9M0Mr+YWeMDONhEzzmOR4XGB6g0hhRgsY3HI0KMuOmw3UhA9dyTOlbgSs0I6BftUNFYyblkfTJncgc+wCkMKUk5Mugy0W3wZbFUioqp8AfMnzNQbygRlpChNinCsLuc7Hdo6tZVr8xZPXfMfkkNybjxgZXvZxyVRIZAqftueCtN3t7HVf11jwLCpTnCnC7HSu8XVLQGMaCO8xLvt9xHS/pMLkG6cXEQ84zJCT655lsdFwF/3sOWRg3Bk8IDBjaVoMZRjyffdeQA6NEJ1G+6fe8AFctdBvYbUXLr3tt37tJMVAYJnKGABldXCFQ1KMDmHgnza2lDUmWNshYWhO1tPBaGreoY7S1+QNXTf3W/YW5OYCvpJlrFfUsTLM7oYdH2Hccl+VJmZ9Ig2v/5+7yCRDIoH2aljExA8dJtjENZTLurlEv/3Fe3CXgnEH96iIPWm/LMIXep0F6QGNBPjc3x0LULCLMIsIsIjxeEWHkJSN9RfgpviLUcskrQsZ+Q1Y+CyGzEDILIY9ZCJkGUnA1ua8kWbbTz0b28KpAM/kTcvjtf0b79peZmJ/V20/84mRf9ElnQGLF1oyKV3wFnoM1/vCGV3/8/HtOTWUp96mP5LOvgo5o6kO8wD889ddfMkho1GLBr7p89f/CdfTJrXNZQf4k9qqNWuN3Zmw2isBpRsL1U+xem/Jhd1xUELO52iYa/W9rbSpH9cNY6IQnU3kaok8ymwTRTzd/1cVplts6opERXpW59KuSRcEaOoLE1xsnC33lzIAGN9XfxE01uqtGsBHXqPUJVA3H1u9Z6jCGjiimkGfV9CXZ+zpN9y+hVZrnv8go3SHn2F1yjtVFFpNOk8fY1uYffMta6hi8jYL0cia1XP5nvJzmIWuA17IOry8AL4fs8jlg9l4as/VJMRsjLWmlpQdw/4rB/Xq8N8j1MeHV+mhCzpM56Mao2QDN32rKvQalgQpkY1i2htxNIPtvI1tk/0X9IDtLHbDKgpGqoNAUtOZnRVsoGqpJ2HzzkHAV0DbAsDAccNZDfo0ylA1MamyJ4tVxlSwpY6r2JGsiBbaMTLTFclMZNg9ilgxWwkgIVYG7XwijTB4btGwLLZtyNivemLK0JQiICyKVJhRiiSIPKwksEecZLooQpysQ51sgprwihoVdFN8qlsEm/uHm/q9UWKJ8RDtDWWYKhstLYtxmhSWKkqxJhQCLmUAXFQ5i/ZpgXoqcdPuAKivgd3KT65bbK1TBjEPNhf1orGu3Pf7Fm20Rk4WdzUPVptJWoxlisqnlQHMEl0KCEVxV1HpfKc1BehPm6ZI3m/8XRoke1xiFA5Q4XtnOMqIro1NynTk0lm9CHBOuzcRxVAvisgXcvWzhjO7qAywMHW8=',
                           'case': 'centipede/massspring/walk',
                           'events': [('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       1.188,
                                       1.188,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                       'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       0,
                                       None,
                                       23.762,
                                       1.368,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_phi',
                                       'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       1,
                                       1,
                                       13.625,
                                       0.621,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                       'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                       'float64, float64)',
                                       2,
                                       2,
                                       0.42,
                                       0.419,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                       'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       2,
                                       2,
                                       0.778,
                                       0.298,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                       'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                       'C), float64, float64)',
                                       3,
                                       4,
                                       0.481,
                                       0.481,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                       'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       2,
                                       2,
                                       11.806,
                                       0.7,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                       'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       6,
                                       11.105,
                                       2.413,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                       'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                       'int64, float64, float64, float64, float64, int64)',
                                       4,
                                       7,
                                       8.692,
                                       2.915,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._candidate',
                                       'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       1.581,
                                       1.007,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                       'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       6,
                                       9,
                                       0.574,
                                       0.574,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._descend',
                                       'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                       'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                       5,
                                       8,
                                       1.439,
                                       1.439,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                       'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       1.879,
                                       1.879,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                       'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                       'int64, int64, int64)',
                                       5,
                                       8,
                                       0.879,
                                       0.879,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                       'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       1,
                                       1,
                                       8.769,
                                       0.634,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       2,
                                       14,
                                       8.135,
                                       0.666,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       3,
                                       15,
                                       7.469,
                                       6.081,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       4,
                                       16,
                                       0.593,
                                       0.593,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       4,
                                       16,
                                       0.795,
                                       0.795,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.hybrid.kernels.place_attached_nodes',
                                       'bench_myriapoda.bodies.hybrid.kernels.place_attached_nodes(array(int64, 1d, '
                                       'C), array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C))',
                                       0,
                                       None,
                                       1.635,
                                       0.962,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                       'array(float64, 3d, C))',
                                       1,
                                       19,
                                       0.673,
                                       0.246,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                       'float64, float64, array(float64, 2d, C))',
                                       2,
                                       20,
                                       0.427,
                                       0.427,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, '
                                       'C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       1.633,
                                       0.394,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.side_sign',
                                       'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                       1,
                                       22,
                                       0.096,
                                       0.096,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, '
                                       'C), array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                       'C))',
                                       1,
                                       22,
                                       1.143,
                                       0.401,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_root',
                                       'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                       2,
                                       24,
                                       0.545,
                                       0.305,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.matvec',
                                       'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                       'float64, float64)',
                                       3,
                                       25,
                                       0.241,
                                       0.241,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                       'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                       'float64, float64)',
                                       2,
                                       24,
                                       0.196,
                                       0.196,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                       'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, '
                                       'array(float64, 1d, C))',
                                       0,
                                       None,
                                       0.339,
                                       0.339,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                       'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, '
                                       'C), float64, array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.268,
                                       0.268,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       0,
                                       None,
                                       1.692,
                                       1.381,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                       'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                       '2d, C), float64, float64, array(float64, 2d, C))',
                                       1,
                                       30,
                                       0.311,
                                       0.311,
                                       False,
                                       True),
                                      ('bench_myriapoda.fused.legged_walk.massspring_chunk',
                                       'bench_myriapoda.fused.legged_walk.massspring_chunk(float64, int64, '
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
                                       'array(float64, 1d, C), array(float64, 1d, C)), Tuple(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                       'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), '
                                       'array(int64, 1d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(bool, 1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, '
                                       'array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C)), Tuple(array(bool, 1d, C), '
                                       'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C)), '
                                       'Tuple(array(float64, 1d, C), array(int8, 2d, C), array(float64, 3d, C), '
                                       'array(int64, 1d, C), array(bool, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C), array(float64, 3d, C)))',
                                       0,
                                       None,
                                       109.307,
                                       11.358,
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
                                       56.594,
                                       7.71,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, '
                                       'C), int64)',
                                       2,
                                       33,
                                       9.931,
                                       6.401,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, '
                                       'C), int64, int64)',
                                       3,
                                       34,
                                       3.53,
                                       3.53,
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
                                       7.91,
                                       4.787,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                       'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                       '1d, C), array(float64, 1d, C), float64, float64)',
                                       3,
                                       36,
                                       0.258,
                                       0.258,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                       'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, '
                                       '1d, C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       3,
                                       36,
                                       1.516,
                                       0.301,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, '
                                       'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       4,
                                       38,
                                       1.215,
                                       1.215,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                       'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, '
                                       'C), array(int64, 1d, C), int64, float64, float64, float64)',
                                       3,
                                       36,
                                       0.285,
                                       0.285,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       36,
                                       0.756,
                                       0.756,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                       'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                       '2d, C), float64, float64, float64)',
                                       3,
                                       36,
                                       0.307,
                                       0.307,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.tips_touching',
                                       'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                       2,
                                       33,
                                       1.266,
                                       1.266,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                       'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, '
                                       'bool)',
                                       2,
                                       33,
                                       0.207,
                                       0.207,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                       'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                       '1d, C), int64, array(bool, 1d, C))',
                                       2,
                                       33,
                                       0.387,
                                       0.387,
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
                                       7.844,
                                       3.292,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                       'array(float64, 1d, C), float64, float64, float64)',
                                       3,
                                       46,
                                       2.343,
                                       1.105,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_normal',
                                       'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       4,
                                       47,
                                       1.238,
                                       0.568,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                       'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                       'float64, float64)',
                                       5,
                                       48,
                                       0.386,
                                       0.386,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                       'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       5,
                                       48,
                                       0.283,
                                       0.283,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                       'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       3,
                                       46,
                                       1.27,
                                       0.623,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                       'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                       'float64, float64)',
                                       4,
                                       51,
                                       0.33,
                                       0.152,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                       'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                       'float64)',
                                       5,
                                       52,
                                       0.178,
                                       0.178,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                       'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                       '2d, C), int64, float64)',
                                       4,
                                       51,
                                       0.318,
                                       0.318,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                       'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, '
                                       'C), array(float64, 2d, C), float64, float64, float64, float64)',
                                       3,
                                       46,
                                       0.265,
                                       0.265,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                       'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, '
                                       '2d, C))',
                                       3,
                                       46,
                                       0.674,
                                       0.674,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                       'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       2,
                                       33,
                                       2.096,
                                       1.873,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       57,
                                       0.223,
                                       0.223,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                       'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, '
                                       'C), array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       2,
                                       33,
                                       2.793,
                                       1.552,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                       'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, '
                                       'int64)',
                                       3,
                                       59,
                                       0.139,
                                       0.139,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                       'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, '
                                       'int64)',
                                       3,
                                       59,
                                       0.18,
                                       0.18,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                       'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       59,
                                       0.33,
                                       0.33,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                       'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                       3,
                                       59,
                                       0.196,
                                       0.196,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                       'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, '
                                       '2d, C), int64, float64, float64, float64, float64)',
                                       3,
                                       59,
                                       0.395,
                                       0.395,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                       'array(bool, 1d, C))',
                                       2,
                                       33,
                                       5.049,
                                       2.071,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3), float64)',
                                       3,
                                       65,
                                       2.978,
                                       1.03,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knee_tip_phi(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, float64, float64, float64)',
                                       4,
                                       66,
                                       1.948,
                                       1.948,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                       'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       33,
                                       0.771,
                                       0.46,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_tip',
                                       'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64)',
                                       3,
                                       68,
                                       0.311,
                                       0.311,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                       2,
                                       33,
                                       2.019,
                                       2.019,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                       'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       33,
                                       6.583,
                                       5.552,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                       'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), '
                                       'float64, float64, float64)',
                                       3,
                                       71,
                                       0.249,
                                       0.249,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._wrap',
                                       'bench_myriapoda.kinematics.legs._wrap(float64)',
                                       3,
                                       71,
                                       0.131,
                                       0.131,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._ik_solve',
                                       'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                       'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                       3,
                                       71,
                                       0.651,
                                       0.651,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, '
                                       '1d, C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                       2,
                                       33,
                                       2.03,
                                       2.03,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                       'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                       1,
                                       32,
                                       2.484,
                                       0.937,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                       'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                       '2d, C), array(float64, 1d, C))',
                                       2,
                                       76,
                                       1.546,
                                       1.546,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.massspring.myriapod.advance_chain',
                                       'bench_myriapoda.bodies.massspring.myriapod.advance_chain(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 1d, C), array(int64, 1d, C), '
                                       'array(int64, 1d, C), array(int64, 1d, C), array(float64, 2d, C), '
                                       'array(int64, 1d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(bool, 1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, '
                                       'array(float64, 1d, C), int64, array(float64, 1d, C), array(float64, 1d, C), '
                                       'int64, array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C))',
                                       1,
                                       32,
                                       36.323,
                                       11.316,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.massspring.kernels.spring_forces',
                                       'bench_myriapoda.bodies.massspring.kernels.spring_forces(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                       2,
                                       78,
                                       0.877,
                                       0.877,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.hybrid.kernels.link_spines',
                                       'bench_myriapoda.bodies.hybrid.kernels.link_spines(array(float64, 2d, C), '
                                       'array(float64, 2d, C))',
                                       2,
                                       78,
                                       0.481,
                                       0.481,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                       'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64, float64)',
                                       2,
                                       78,
                                       1.533,
                                       1.533,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                       'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       2,
                                       78,
                                       1.434,
                                       1.434,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.hybrid.kernels.rigid_segments_step',
                                       'bench_myriapoda.bodies.hybrid.kernels.rigid_segments_step(array(int64, 1d, '
                                       'C), array(int64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(bool, 1d, C), array(float64, 3d, C), array(float64, 1d, C), int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(int64, 1d, C), '
                                       'array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C))',
                                       2,
                                       78,
                                       20.683,
                                       7.307,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                       'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       3,
                                       83,
                                       0.716,
                                       0.595,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._cross',
                                       'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, '
                                       'float64, float64, float64)',
                                       4,
                                       84,
                                       0.121,
                                       0.121,
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
                                       3,
                                       83,
                                       12.66,
                                       9.935,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, '
                                       '2d, C), float64, float64, float64, array(float64, 2d, C))',
                                       4,
                                       86,
                                       0.256,
                                       0.256,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                       'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, '
                                       'float64)',
                                       4,
                                       86,
                                       0.232,
                                       0.232,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                       'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                       '2d, C), float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       4,
                                       86,
                                       0.219,
                                       0.219,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64)',
                                       4,
                                       86,
                                       0.52,
                                       0.52,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64)',
                                       4,
                                       86,
                                       0.321,
                                       0.321,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                       'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       4,
                                       86,
                                       0.874,
                                       0.245,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                       'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       5,
                                       92,
                                       0.628,
                                       0.457,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                       'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, '
                                       'float64, float64, float64, float64, float64)',
                                       6,
                                       93,
                                       0.172,
                                       0.172,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                       'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                       'float64)',
                                       4,
                                       86,
                                       0.146,
                                       0.146,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                       'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, '
                                       'float64)',
                                       4,
                                       86,
                                       0.158,
                                       0.158,
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
                                       2.547,
                                       1.56,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, '
                                       '1d, C), float64, array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       2,
                                       97,
                                       0.987,
                                       0.987,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.energy',
                                       'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.54,
                                       0.54,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                       'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                       'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       0,
                                       None,
                                       0.836,
                                       0.836,
                                       False,
                                       True)]},
 'massspring-legless-dry': {'args': 'eNqVVFtrE0EUNm0uFkQxYaVaH0LUsoYQqIrPXQsLstQHqeTBlrDZHTNbktmwmUXyIPiUKMxbxx/iXxIU8UH9CZ4zs7u5bar20GTmnDPf+c4t74ufPpevqL8zaZriNouHPbfthRFp88mIjNtub8wj1+NS1Lqo6UbECxnoYo+HkbyQouKFo0lE+lJcXzfurgGOPXfgRmN495xx0ifK7WovDgY8YKAuh71zAvEu5IuZfCdNUWTukEhRChh/+gRdA/428DmVzqEoj4M+I778IEpdL/SJdO7EM/lS0m1azkmGjSbqAGhWFLkTCEKvJWFKPprUS1oRJXsQunzBTm+IyhvUAQd60zmkNeeuCgX8/GAonYIoD9xJGEOlCkcyZW24GMdMXrbqB36rfvRQpnSPvxQ03wYKhzAGbaYXfZqB8jIVHo2cC4iRKuaqxKBNjXxZhVl6cwmcNiXHJazNF2ODBbuwm9V+D9T3nC16nz6g+2s1faRrSs3jr1k1mwmxPJztDTiPM5xvGgeJWAmYpS8WXGwQQ3Fvqk9bCZ4t/Q99sqg9legxXe7pSs7GX1prJylUROVZGA6Iy5ZHstgDrYRZrOrEkQT67yz4lGO9OWpqqx/B+ZZ21vyVQHibWtMkYpOe0lPNNZXVOhpQx0JSx5quo4qSTThU8UchjWMgIIjCEXtrewk/GtwNGMGfhdJJPBqQpc3UO2vSzvKUipIXxoxLpwKEkCARO69YELITXOSFOp3jS2gHUFX211i1VtL3M6T6M6G6LywV3lQe9Ww0/uOgUv9VyPqxWEdfzSRWogGUOpuWz5jvwj+Y5r2zANJPpJkOpBpGaMFMKntzls1xXk+3cns637Df88Q0IYTCePht46eKp+jkJqC9dRqrBDoLQ1XVBHQf5jP1Pd1M0v4DUV1F3g==',
                            'case': 'worm/massspring/flat',
                            'events': [('bench_myriapoda.world.terrain_kernels.signed_distance',
                                        'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        0,
                                        None,
                                        9.811,
                                        0.738,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_phi',
                                        'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        1,
                                        0,
                                        6.127,
                                        0.275,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                        'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                        'float64, float64)',
                                        2,
                                        1,
                                        0.239,
                                        0.239,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                        'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        2,
                                        1,
                                        0.472,
                                        0.191,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                        'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                        'C), float64, float64)',
                                        3,
                                        3,
                                        0.281,
                                        0.281,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                        'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                        'C), float64, float64, float64)',
                                        2,
                                        1,
                                        5.142,
                                        0.288,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                        'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        3,
                                        5,
                                        4.853,
                                        0.724,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                        'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, int64)',
                                        4,
                                        6,
                                        4.129,
                                        1.12,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._candidate',
                                        'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        1.1,
                                        0.747,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                        'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                        'float64, float64, float64, float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        6,
                                        8,
                                        0.353,
                                        0.353,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._descend',
                                        'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), '
                                        'int64, float64, float64, float64, float64, float64, float64, float64, '
                                        'int64, int64)',
                                        5,
                                        7,
                                        0.764,
                                        0.764,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                        'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                        'int64, int64, float64, float64, float64, float64, float64, float64, '
                                        'float64, int64, int64)',
                                        5,
                                        7,
                                        0.808,
                                        0.808,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                        'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                        'int64, int64, int64)',
                                        5,
                                        7,
                                        0.339,
                                        0.339,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                        'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                        'float64, float64, float64, float64)',
                                        1,
                                        0,
                                        2.945,
                                        0.188,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, '
                                        'C), float64, float64, float64, float64)',
                                        2,
                                        13,
                                        2.757,
                                        0.206,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below_counted',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below_counted(array(float64, '
                                        '1d, C), float64, float64, float64, float64)',
                                        3,
                                        14,
                                        2.551,
                                        2.078,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                        'int64, float64, float64, float64)',
                                        4,
                                        15,
                                        0.196,
                                        0.196,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                        'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                        '1d, C), float64, float64, float64, float64)',
                                        4,
                                        15,
                                        0.277,
                                        0.277,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.fill_activation',
                                        'bench_myriapoda.controllers.muscle_waves.fill_activation(array(float64, 2d, '
                                        'C), float64, array(float64, 1d, C), float64, float64, int64, array(float64, '
                                        '3d, C))',
                                        0,
                                        None,
                                        0.433,
                                        0.178,
                                        False,
                                        True),
                                       ('bench_myriapoda.controllers.muscle_waves.segment_activation',
                                        'bench_myriapoda.controllers.muscle_waves.segment_activation(array(float64, '
                                        '2d, C), float64, array(float64, 1d, C), float64, array(float64, 2d, C))',
                                        1,
                                        18,
                                        0.254,
                                        0.254,
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
                                        22.989,
                                        6.628,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._corner_major',
                                        'bench_myriapoda.bodies.massspring.kernels._corner_major(array(float64, 2d, '
                                        'C), array(float64, 3d, C))',
                                        1,
                                        20,
                                        0.187,
                                        0.187,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._flat_ground',
                                        'bench_myriapoda.bodies.massspring.kernels._flat_ground(int64, '
                                        'array(float64, 1d, C))',
                                        1,
                                        20,
                                        3.786,
                                        1.08,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                        'array(float64, 1d, C), float64, float64, float64)',
                                        2,
                                        22,
                                        2.706,
                                        1.062,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                        'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                        'C), int64, float64, float64, float64)',
                                        3,
                                        23,
                                        0.722,
                                        0.722,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._other_normal',
                                        'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                        '1d, C), float64, float64, float64)',
                                        3,
                                        23,
                                        0.921,
                                        0.564,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                        'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                        'float64, float64)',
                                        4,
                                        25,
                                        0.228,
                                        0.228,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                        'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                        'float64, float64, float64)',
                                        4,
                                        25,
                                        0.13,
                                        0.13,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._column_forces_flat',
                                        'bench_myriapoda.bodies.massspring.kernels._column_forces_flat(array(float64, '
                                        '3d, C), int64, bool, array(float64, 1d, C), array(float64, 1d, C), uint64, '
                                        'int64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C))',
                                        1,
                                        20,
                                        5.56,
                                        5.56,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_vectors_c',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_vectors_c(array(float64, '
                                        '3d, C), array(float64, 2d, C))',
                                        1,
                                        20,
                                        0.393,
                                        0.393,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.spine_rows',
                                        'bench_myriapoda.bodies.massspring.kernels.spine_rows(array(float64, 3d, C), '
                                        'int64, array(float64, 1d, C), uint64, uint64)',
                                        1,
                                        20,
                                        0.393,
                                        0.393,
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
                                        4.403,
                                        2.951,
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
                                        1.452,
                                        1.452,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                        'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64, float64, float64)',
                                        1,
                                        20,
                                        0.71,
                                        0.71,
                                        False,
                                        True),
                                       ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                        'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                        'array(float64, 1d, C), float64, float64, float64, float64, float64, '
                                        'float64, float64, float64)',
                                        1,
                                        20,
                                        0.792,
                                        0.792,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels._node_major',
                                        'bench_myriapoda.bodies.massspring.kernels._node_major(array(float64, 3d, '
                                        'C), array(float64, 2d, C))',
                                        1,
                                        20,
                                        0.139,
                                        0.139,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_rest_lengths',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_rest_lengths(array(float64, '
                                        '2d, C), bool, array(int64, 1d, C), array(int64, 1d, C), array(int64, 1d, '
                                        'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                        'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C))',
                                        0,
                                        None,
                                        0.553,
                                        0.314,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.fibre_stretch',
                                        'bench_myriapoda.bodies.massspring.kernels.fibre_stretch(array(float64, 2d, '
                                        'C), int64, int64)',
                                        1,
                                        36,
                                        0.091,
                                        0.091,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.face_scales',
                                        'bench_myriapoda.bodies.massspring.kernels.face_scales(array(float64, 2d, '
                                        'C), bool, array(float64, 1d, C))',
                                        1,
                                        36,
                                        0.148,
                                        0.148,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.massspring.kernels.lattice_energy',
                                        'bench_myriapoda.bodies.massspring.kernels.lattice_energy(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(float64, 1d, C), array(int64, 2d, C), '
                                        'array(float64, 1d, C), array(float64, 1d, C), float64)',
                                        0,
                                        None,
                                        0.353,
                                        0.353,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.best_fit_frames',
                                        'bench_myriapoda.bodies.segment_frames.best_fit_frames(array(float64, 2d, '
                                        'C), array(float64, 2d, C), array(int64, 1d, C), array(int64, 1d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                        'array(float64, 2d, C), array(float64, 2d, C))',
                                        0,
                                        None,
                                        2.327,
                                        0.41,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                        'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                        'array(float64, 2d, C))',
                                        1,
                                        40,
                                        1.916,
                                        0.715,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                        'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                        'float64, float64, float64, float64, float64, float64)',
                                        2,
                                        41,
                                        1.201,
                                        1.201,
                                        False,
                                        True),
                                       ('bench_myriapoda.bodies.segment_frames.segments_touching',
                                        'bench_myriapoda.bodies.segment_frames.segments_touching(array(float64, 2d, '
                                        'C), array(int64, 1d, C), array(int64, 1d, C), int64, array(float64, 1d, C), '
                                        'float64, array(bool, 1d, C))',
                                        0,
                                        None,
                                        0.55,
                                        0.55,
                                        False,
                                        True)]}}
