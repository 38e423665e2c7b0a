"""Compile plans recorded by ``python -m bench_myriapoda.harness.cold_compile --record``: generated, do not edit.


"""
NUMBA_VERSION = '0.68.1'
PLANS = {'fem-legged-dry': {'args': 'eNrtGk1vG0XUcWy3BVRQS2lxP2QtEnKjxVaTFapvuJWQkOseUJGCUBSt15vMtvauZa8FUYRVVUoMYi/Q7aUHiohy5OuaAx+i0PJxQv0NiCMHhMSNefOxn7POdw6tM0qy8/HevHnz3pt5b97NzJ3PplLkZ84tFp0XzX67oZY0q6uX7KWO3iupjZ7dVTXbdY7PQ8t8V9csE7f1Ndvqurdd55BmdZa6+qLrHI13xhGanSXy4TrZarerLsGow42+0bINEzfmrMZ1HU932706dN93i062CcNdNIlyzqkYtp6mttQuIHu9ZakAhp5hgBlTbeuYvAXoeFWBWQz7XaNpI7f2mpOd16ym7tbO9Ifumy4e3DTabi3t5FrqktXHy5247HIUJ1QgtMgQyYXpply4fN7lOOofpwkSIBEd4fOjZ0n9OefQG6atL+rdAG3ohJM1TCAKncS05HrGoqk33Q/QqVqeojpdS6Mz6Cw65xynk5Ph3tSoUP8kYdI8hp1ksFHCZzzo2yOgJxKgL3jQLoW2MUgZVaDAp0I/kWTH8coBvOEV+VjvMJqqqDLEQDJGlYdihyv0C0aMaoJPWVDBReYNfhProF15cYmiCcGMQEe72Gc+kb5Aj4RZKfGCVyevkBGSP8pnOm2uUDAPQ4BoYN0q6S0TtApScCPUpCH8l1ZFS2Y8lYbeFBguvKueZua59mQ87UFnk3RHiejOF74oUfolTr9MVP50TOWxhbFVw9SJ1l/rd1p6UOuz1LgA1VVCb9uTwk4RN3G+JujqJctq6aoZ1tVMA7e6WDmPceXkonyMrg76g5J8j0nywCt0SweEgIqwKGRExRtPvxWEuE45Wc3qm7Zbk5FKyL3hHHnLNCzzGuxCgGC8zgHZNACu4s1oOitk4DtxamWhjstCgycLrYks3GBZoONzLlqof8lY05x9NJlKke0rCsbKBTEJe9kc4sMBtm1G5cxOid8RBy88yc0zu9iBBNz7KRk7JmCzlSl7wUxK3XnQ8q+YlrNjCt2s5ZjRuuWbKfQRGOkh2IJsJpWiJmpsEcYWYWwRHi+LMPKSEb8ifO1dEa5kwleEhPkiUj42IWMTMjYhj5kJ2YudIleTbwKRjxvOU1exl9pM8iIjDuRd7kVXcRkQf475055v9nQwXhW47NwtssFVVLa9wFJ7q27ZFhywsJ4KgkZzvtP9E+PBmvOv0LxOiyzAlgyL0FoIG7chqnto72a4IKzXfw4IQmCPRXsOvng5EjK4R+ovB8IEub4f00NTH6JTtRdCwcWJQHgEs/55Slo/Egdbrz9ghG14wYoqKRX2t8zqEosT0CDRp7XTjKaI1FUIgjLasGHDb+1hJGBTkZNFS5yDNT7kEjj7djrhjN+NuRKKbF8oh/0DvyJsXUdGk7Y/CPaH1un9OqamN/FF1+u/iPQ8GCeU2W8lYMdzLCTo69IDGLXqonOOFFShKDMJG+YgCPg5m/ecY428wzLG7ag36Zgr1Ne4Bz4E0zAZNw3oD3Sf9K7N/pkWed8HQKg8Vvyx4u+L4otPM3L0/OodPX95R89YDsdyuD9yWDhok5p4JqzXf6OSvwonQtrJLRh6qwlP7o2Wpd2A1zQNqYaJ+52jhtmzVVPT57WW2sNdLzV0U0Pz7aWuoXasplpqWE1D75UW9HaJN2KwS4DpMmC5oi/2wKNam/17MpUKtxefTKeDy8LY2IyNzeNtbIi1eST0rztw4w570mrMk85gYi6CH30YTUFSzEmKqVFLIw37zk3+7g7D/JyYhfq3bEqFvf0H51iOg9ON8cG/88Dh5Vwh71ZH4u9WRfQfea9HeJZ/yPO6wKme3oZTvd2HdDm+ehI4/54Hzp3ftxY1v7gbAxta5+5ioMomwZqF+g/BNBGFJMBUyfshfV+krhnJtOEZKzxLJjmvYpnmz1RiOTiQNCGoVoUJRZHMG5lNPsBULUMZugRwMGSkD6ivySemOS8gbNvKePLXGMtR8jN48hQMD5Q5uBTollY8kio07SY5P4lGmwZkKF2cTFguc5ZL/miaryT5+VAcgcTSYGBpA75GntdE47GHsSZFo7FYA/NYEyexXJ/g3VxICu8VZoiA/EgF5PorE6lUhIF+lc1FBpE/0DHw863saJ4V75dphhVspJ+cNSA7J4UEAOVXvC2QiAQGVg8kLAMLKQiNIvPpSX4QdNzHnnmF5ouRLC1WNiAe6GduFf3QX5FQ5VXyoxLYhI0bNNRIZ6QyEo44SnQN3meAtVFcgi4iwFhbuQAr1MDaXlJahc9d5jmENhMgmYubXvofh5cxHg==',
                    'case': 'centipede/fem/walk',
                    'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.48,
                                0.48,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.137,
                                0.137,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                0.249,
                                0.249,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                'array(int64, 1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.202,
                                0.202,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                0,
                                None,
                                9.698,
                                0.459,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_phi',
                                'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                1,
                                4,
                                5.311,
                                0.299,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                'float64)',
                                2,
                                5,
                                0.172,
                                0.172,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                2,
                                5,
                                0.315,
                                0.119,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                'float64, float64)',
                                3,
                                7,
                                0.196,
                                0.196,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                'float64, float64, float64)',
                                2,
                                5,
                                4.526,
                                0.305,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                9,
                                4.22,
                                0.806,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, int64)',
                                4,
                                10,
                                3.415,
                                1.184,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._candidate',
                                'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.917,
                                0.475,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                6,
                                12,
                                0.443,
                                0.443,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._descend',
                                'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.498,
                                0.498,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                'int64, float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                5,
                                11,
                                0.54,
                                0.54,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), int64, '
                                'int64, int64)',
                                5,
                                11,
                                0.275,
                                0.275,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                1,
                                4,
                                3.927,
                                3.353,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                2,
                                17,
                                0.258,
                                0.258,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                2,
                                17,
                                0.317,
                                0.317,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                0,
                                None,
                                0.852,
                                0.196,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.side_sign',
                                'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                1,
                                20,
                                0.053,
                                0.053,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, float64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                1,
                                20,
                                0.602,
                                0.199,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_root',
                                'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), array(float64, 1d, C))',
                                2,
                                22,
                                0.309,
                                0.156,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.matvec',
                                'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                23,
                                0.153,
                                0.153,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                'float64, float64)',
                                2,
                                22,
                                0.095,
                                0.095,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, 1d, '
                                'C))',
                                0,
                                None,
                                0.157,
                                0.157,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_poses',
                                'bench_myriapoda.bodies.fem.myriapod.block_poses(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C))',
                                0,
                                None,
                                2.31,
                                0.335,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.block_centroids',
                                'bench_myriapoda.bodies.fem.myriapod.block_centroids(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C))',
                                1,
                                27,
                                0.158,
                                0.158,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.polar_rotation',
                                'bench_myriapoda.bodies.fem.kernels.polar_rotation(array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                1,
                                27,
                                1.818,
                                0.285,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                2,
                                29,
                                1.532,
                                1.532,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                'float64, array(float64, 2d, C))',
                                0,
                                None,
                                0.125,
                                0.125,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                'array(float64, 3d, C), array(float64, 4d, C))',
                                0,
                                None,
                                0.458,
                                0.318,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, 2d, '
                                'C), float64, float64, array(float64, 2d, C))',
                                1,
                                32,
                                0.139,
                                0.139,
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
                                59.214,
                                9.564,
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
                                31.487,
                                3.871,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                'int64)',
                                2,
                                35,
                                1.022,
                                0.716,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                'int64, int64)',
                                3,
                                36,
                                0.307,
                                0.307,
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
                                35,
                                4.214,
                                2.863,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                '1d, C), array(float64, 1d, C), float64, float64)',
                                3,
                                38,
                                0.131,
                                0.131,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                3,
                                38,
                                0.648,
                                0.125,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                'float64, float64, float64, float64, array(int64, 1d, C))',
                                4,
                                40,
                                0.522,
                                0.523,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                'array(int64, 1d, C), int64, float64, float64, float64)',
                                3,
                                38,
                                0.126,
                                0.126,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                38,
                                0.305,
                                0.305,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                '2d, C), float64, float64, float64)',
                                3,
                                38,
                                0.141,
                                0.141,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.tips_touching',
                                'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                2,
                                35,
                                0.581,
                                0.581,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                2,
                                35,
                                0.092,
                                0.092,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, 1d, '
                                'C), int64, array(bool, 1d, C))',
                                2,
                                35,
                                0.171,
                                0.171,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, C), '
                                'array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                2,
                                35,
                                6.741,
                                1.518,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                'array(float64, 1d, C), float64, float64, float64)',
                                3,
                                48,
                                4.305,
                                3.646,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._other_normal',
                                'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, C), '
                                'float64, float64, float64)',
                                4,
                                49,
                                0.659,
                                0.299,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), float64, '
                                'float64)',
                                5,
                                50,
                                0.21,
                                0.21,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                'float64, float64)',
                                5,
                                50,
                                0.15,
                                0.15,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                'float64, float64, float64)',
                                3,
                                48,
                                0.485,
                                0.205,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                'float64, float64)',
                                4,
                                53,
                                0.16,
                                0.075,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                'float64)',
                                5,
                                54,
                                0.085,
                                0.085,
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
                                0.131,
                                0.131,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, C))',
                                3,
                                48,
                                0.3,
                                0.3,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                'array(float64, 2d, C))',
                                2,
                                35,
                                3.809,
                                0.82,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                3,
                                59,
                                2.895,
                                2.895,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), int64, '
                                'float64, float64, float64)',
                                3,
                                59,
                                0.094,
                                0.094,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 1d, C), float64, array(bool, 1d, C))',
                                2,
                                35,
                                1.028,
                                0.555,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                3,
                                62,
                                0.056,
                                0.056,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                3,
                                62,
                                0.071,
                                0.071,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                'int64, float64, float64, float64)',
                                3,
                                62,
                                0.125,
                                0.125,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                3,
                                62,
                                0.068,
                                0.068,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, C), '
                                'int64, float64, float64, float64, float64)',
                                3,
                                62,
                                0.153,
                                0.153,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'array(bool, 1d, C))',
                                2,
                                35,
                                4.211,
                                0.929,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, array(float64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                'float64, UniTuple(float64 x 3), UniTuple(float64 x 3), float64)',
                                3,
                                68,
                                2.631,
                                2.15,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, C), '
                                'float64, float64, float64, float64)',
                                4,
                                69,
                                0.481,
                                0.481,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), array(float64, '
                                '1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3))',
                                3,
                                68,
                                0.651,
                                0.651,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C))',
                                2,
                                35,
                                0.401,
                                0.246,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.leg_tip',
                                'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, 2d, '
                                'C), array(float64, 1d, C), float64, float64, float64, float64)',
                                3,
                                72,
                                0.155,
                                0.155,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                2,
                                35,
                                0.988,
                                0.988,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, array(float64, 2d, C), '
                                'array(float64, 2d, C))',
                                2,
                                35,
                                3.056,
                                2.598,
                                False,
                                True),
                               ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                'float64, float64)',
                                3,
                                75,
                                0.125,
                                0.125,
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
                                0.268,
                                0.268,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                'bool, array(bool, 1d, C), array(float64, 1d, C))',
                                2,
                                35,
                                1.301,
                                1.301,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.myriapod.carry_blocks',
                                'bench_myriapoda.bodies.fem.myriapod.carry_blocks(array(float64, 2d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), array(float64, '
                                '3d, C), array(float64, 2d, C), array(bool, 1d, C))',
                                2,
                                34,
                                0.355,
                                0.355,
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
                                16.372,
                                6.07,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered',
                                'bench_myriapoda.bodies.fem.kernels.elastic_forces_gathered(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, '
                                '2d, C), array(float64, 2d, C), array(uint64, 1d, C), array(uint64, 1d, C), '
                                'array(float64, 2d, C))',
                                3,
                                81,
                                7.413,
                                0.45,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), array(int64, '
                                '2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                0.388,
                                0.388,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                3.255,
                                3.255,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                2.797,
                                1.567,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64)',
                                5,
                                85,
                                1.229,
                                1.06,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, float64, '
                                'float64, float64, float64, float64, float64)',
                                6,
                                86,
                                0.169,
                                0.169,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels._gather_pass',
                                'bench_myriapoda.bodies.fem.kernels._gather_pass(array(uint64, 1d, C), array(uint64, '
                                '1d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                4,
                                82,
                                0.523,
                                0.523,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, 1d, '
                                'C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                3,
                                81,
                                1.893,
                                0.458,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), array(int64, '
                                '1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                4,
                                89,
                                1.435,
                                1.435,
                                False,
                                True),
                               ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, 1d, '
                                'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                'float64, float64)',
                                3,
                                81,
                                0.425,
                                0.425,
                                False,
                                True),
                               ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, array(float64, '
                                '1d, C), float64, float64, float64, float64, float64, float64, float64, float64)',
                                3,
                                81,
                                0.571,
                                0.571,
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
                                1.436,
                                0.861,
                                False,
                                True),
                               ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, C), '
                                'float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, C), '
                                'array(float64, 4d, C))',
                                2,
                                93,
                                0.575,
                                0.575,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '2d, C))',
                                0,
                                None,
                                0.391,
                                0.391,
                                False,
                                True),
                               ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), array(float64, '
                                '1d, C), array(float64, 1d, C))',
                                0,
                                None,
                                0.407,
                                0.407,
                                False,
                                True),
                               ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), int64, '
                                'int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                0,
                                None,
                                0.542,
                                0.542,
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
 'hybrid-legged-dry': {'args': 'eNrtHFlvG8eZokjqqOsaSd24TFwQRFMwxkJuJKII38q4VR3QzoORogHSYLHcXWpWInfp5VIWYYQwAlhs0XkpvIHRFm6cNGfTJr0PFOkF5K2P7mOLPvcH9DX9vpnZS1xSEkUJsbxaiJyd85uZ7575eCPzSvZiiv296JZK9PNmt1VXllTL1pecXlvvLCn1jmMrquPSh2XMkW1dtUzI66qOZbu3XDqnWu2era+59ORw4XCHZrvHEi7NVm1b6WGt+XrXaDqGCZk5q76uw3C33GcH7ktuiWY1rO6SWZKjZ4Z666hKU7Gxs9WmpWAzckI0zJhKSwfwGljwlTKOYjjXDM0hbu2rNCurlqa7tce6A/eKC5U1o+XW0jTXVHpWF6Y7c8H1ujitIKAl0ZFUWNakwoUnXK+Py26adYIgkgVvfPIZ9n6Kzj1jOvqabodgI6dp1jARKPIIwJLrGGumrrnfIWdqed7Vo7U0eYycJV+gD/PBWXV/aFK4/OqIQfPQdla03Qn4it/6lTGtZ0a0ftJv/X3e2oEm50kFH0yWeZIUneF+pVC/0RkFvf5AwFQllYGL/ZDiABpLkMzj40RfeAprjMvCpBTzAo/kZQRZooAX5eOfnd1E2ozpjheJZH4kfKGSKjxF/ymLb1hrfNsOQVjE2kGNItsC6Sbrrxj0GWwVz67wZv54oSniQm/z9SwO/AZleCI761Nn3qOgjE9B5Owo+invoJ/XAnQqBvPhS4dk/+gQ2QOXcRTD1BnlP9dtN/Uw5Wc5g0Goqwzelo+J7VJoTUfQ69OW1dQVM0qvmTrkukCgD3kE6qHzQ3x2WB7G5tsCm/v+wzeozwCoxD5lVqPi1+fpMiEeXdGsanVNx61JRGHgbtCFb5qGZT6HuxACGObZZ5uGjauwGRq9ySq+MAytFEvnUizTk2I5ihS7wVIMnb/oksbl18XSaM/fm02l2PaVYupKhXgQppkdWYcjzNsNypVJgZ9oBZ98kLNXDrADI/o+TMyYGIDdZlaexmJy6J5AKv+JoHIhdMiNWk4wrZcDNkW+h0x6gLwgm0mlOItKOELCERKOcLw4wlglY1hFeMNXES5loirCiPF2YHnCQhIWkrCQY8ZCprFTTDV5M+T92KCLz4KVqu20IkE3weLbYZPKMxw964wb6OeZ3VZhZvON2imaaxh6UwP7k86oLp256tL0pg2Jay5d2ACjtaU4BhRkCNSC7C343wTLrmFs6fA+rziOXLe0HtTGZNNSlaZLF5uGuSGbYC+DyZu50kF/W/pKHdJXnVYb0poDBjQ9aZgdRzFVXVabSgeqfrGumyqRWz3bUNqWpixB1wZa0LA6hq7BSFvY44kL/P1p9noLGW99JpUK55Y+OYxzf73Gcq/9sLSI7+2ApO4NKDIYOr4VQseIq2IoA5FOYghXHC70/G9V7ktg2Dgfo3Kjn4Gp3HQ17BLYxf5fGS+w3/YENv1TrLRemT6zHb+Fk/Brthvv+HZLjJco7I4mXwr5h3LdwKFLzn2XnKl9LuJZnonxi32WA9GNekJ9t9hdAcg9xmeqbGfDn9zNd6OWH97jEvlIeH+qgC330OsIFP2NmTgL6z7boql5q6KwxVF63PZI7I2h/Lu+jvqv9AgddRf+JHo+AJdZjtF377cN3ZcWMFl2Nxbu7t4lwwQy5L7oYG/LyPjiT+OlFFeCBsiIZmOEDShJ2ygVvhwrapbHC5X3fKGyuqtBt5fpsXn8bJS09bS7itDxyj6H/VQchxX+deZbf+HwfOtsIX7uL8THk/CZKRoBB1foJjSGQjv4/qgdrLDzQWmswxHKGUIWx+k+AZP/wF95a6wXIsLK91k62lD5xXhcrfiHflVmg5TFOR3H2lNxWCu0Aoa1396H+rc8iVL4S19CdmYmk5CHgaIr07YlJjQFVqYxmd353a88fXYUSZTW07A76yfhg/yP/Jv8l1XVnn88N1ZdPDzMlxJMOXJMkR5wuSIl+nuivx9b/V2ajvocr80yUf9rX9Sfy3miPiGphKSOL0kVpkRThQdd8haOWr0sJPrl0euXY6zc33DZsY32SZrcoVlxKJVViWKYmP8BLY44xyK9um1oS/zAbPEie7ukr4kzrB/OpVJBXik5zjrs4yyPthLRn4j+RPQnoj8R/YnoH7UZTPb/drQvPxqeoQwduWdgHZ7CA/d5cg5Dpx7hPdVBh1DJWaJ5kRlYLYicalz+nRiyLKJDwmNcH27O0T5o/nu/OcZW8GsWC3Fe1RV0qFZ4BMb6Erwwp/vLw0dFy/s4KtpvwIU0vAbMXv+Df67xj73drnxqj6gci5yReR4MM8u7XuD4YzicqMzCnqrsnjk/FuIHQCway4ts8mKjRsffXOdRU5WhOC08Sol5rcYGne2It5LE4H2A6jo+A5c17A8E6H1+luUNzGOjEOX2FRUXzHEoji2I98rzZux+UX4QbYMBZzd9kCo8PGt0DFtV3JDrszp9FkyGSy55S14MavMotWIQM+d14EW84dT63hy9aDZ+b28eKGno1p4CxXgSrdHTXrGHJIWtwgpDkA85gqyvIYFGFzB4FWOxSuwDC/pBlJ2zM7rOK5d4XB1uZBCS12c7V4wgAMnf9LegyDAwNHsE4TouIW/iLUjfQ2kWBFjBIMDYW4reJbGP/GtM9/Zwj+hOibxB3qQ5U27Yuu7SjKM7GJP7tZZsmJvwrlp6A95b3Y7axPIWu2OYuSpfw2qr8jXL3oDERZGYM0xVbju2SFkNaJxp63bLpQudjZ7cMOyOA4WYZtWymLoEPTTaPAMTqtXkiU28CJlrN0QRJHgRJFjRAl6PlPGiJNb3gKnzhINW5OPjrcgN3Tb1JkxlfvXrly9BP8KM/E86lfJyEqMmMWqO6xWfP4eUsdsjrvjcIW+Rt8k7g3FOGdtYMzSZe2/oYtVxFJW0dJOF52u0FmRM5ULPX+KhHn+hB1jdj8mr5C55bf0lYO70BEYTO4Yirl6fIEqzIetbDgDZccnr9NNGq91tdnRZBdB1vK5t2Sp85xzLvtrVGXtZ/xH2lA3uUNOPj8rV9Am+rfPXUdszfFvnTonOrdnKpuHg7XdHt215wzA1JohsYPmLDdtQ5RZweeD2GXxBeUJ6nfDyf8uymxpffoulj/bKzt/GY+NuV3ZgCbINWXEw1nuLf+e25LbNQgNsvWNoXRR12U4bENYl79GZKy5NP4OxBaoF0ssGKevS2SZS3qxirsECQSsMENgw8QP7cxR7TXewltIKrdz8BQtEjAFtmNDbxPv/IicxmI/61s7f/VvoUvi3NapCM82DclhmSIPxJ8VBoCRy/TX0kh/3QxZ7zyyKcaM6ZNH7nYqKAKa4HVWnd3YTUwTZ63dRFYfW6++juv0hfvyTmc9he2B4QpHJ+qquZ/UFY0niPx9HeZHfwWDTyHs2VH4Xw2n/SxlAvdc9ibfTmE3rmXl8OoRP4zyfWdhu8FlMUO7/+ocklgmMLH3p/7YFPf0=',
                       'case': 'centipede/hybrid/walk',
                       'events': [('bench_myriapoda.bodies.fem.kernels.rest_shape',
                                   'bench_myriapoda.bodies.fem.kernels.rest_shape(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.984,
                                   0.984,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.lumped_mass',
                                   'bench_myriapoda.bodies.fem.kernels.lumped_mass(array(int64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.314,
                                   0.314,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients',
                                   'bench_myriapoda.bodies.fem.kernels.pack_tet_coefficients(array(float64, 3d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.57,
                                   0.57,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_cholesky',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_cholesky(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.534,
                                   0.534,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.615,
                                   0.615,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                   'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   0,
                                   None,
                                   19.409,
                                   0.589,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_phi',
                                   'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   1,
                                   5,
                                   10.313,
                                   0.745,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                   'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), float64, '
                                   'float64)',
                                   2,
                                   6,
                                   0.394,
                                   0.394,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                   'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   2,
                                   6,
                                   0.677,
                                   0.255,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                   'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, C), '
                                   'float64, float64)',
                                   3,
                                   8,
                                   0.422,
                                   0.422,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                   'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, C), '
                                   'float64, float64, float64)',
                                   2,
                                   6,
                                   8.497,
                                   0.617,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                   'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), int64, '
                                   'float64, float64, float64)',
                                   3,
                                   10,
                                   7.88,
                                   1.552,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                   'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, int64)',
                                   4,
                                   11,
                                   6.329,
                                   1.913,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._candidate',
                                   'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   1.45,
                                   0.856,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                   'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   6,
                                   13,
                                   0.594,
                                   0.594,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._descend',
                                   'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                   'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                   5,
                                   12,
                                   1.198,
                                   1.198,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                   'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), int64, '
                                   'int64, float64, float64, float64, float64, float64, float64, float64, int64, '
                                   'int64)',
                                   5,
                                   12,
                                   1.205,
                                   1.205,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                   'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                   'int64, int64, int64)',
                                   5,
                                   12,
                                   0.562,
                                   0.562,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                   'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   1,
                                   5,
                                   8.507,
                                   7.343,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   2,
                                   18,
                                   0.504,
                                   0.504,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   2,
                                   18,
                                   0.66,
                                   0.66,
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
                                   1.065,
                                   0.664,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                   'array(float64, 3d, C))',
                                   1,
                                   21,
                                   0.401,
                                   0.158,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                   'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, float64, '
                                   'float64, array(float64, 2d, C))',
                                   2,
                                   22,
                                   0.243,
                                   0.243,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   0,
                                   None,
                                   1.056,
                                   0.208,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.side_sign',
                                   'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                   1,
                                   24,
                                   0.069,
                                   0.069,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                   'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, C), '
                                   'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                   'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   1,
                                   24,
                                   0.78,
                                   0.264,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_root',
                                   'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                   2,
                                   26,
                                   0.397,
                                   0.222,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.matvec',
                                   'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   27,
                                   0.175,
                                   0.175,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                   'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                   'float64, float64)',
                                   2,
                                   26,
                                   0.118,
                                   0.118,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                   'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, array(float64, '
                                   '1d, C))',
                                   0,
                                   None,
                                   0.148,
                                   0.148,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                   'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, C), '
                                   'float64, array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.114,
                                   0.114,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                   'array(float64, 3d, C), array(float64, 4d, C))',
                                   0,
                                   None,
                                   0.616,
                                   0.484,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                   'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                   '2d, C), float64, float64, array(float64, 2d, C))',
                                   1,
                                   32,
                                   0.132,
                                   0.132,
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
                                   142.261,
                                   16.577,
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
                                   69.416,
                                   9.166,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, C), '
                                   'int64)',
                                   2,
                                   35,
                                   2.043,
                                   1.447,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                   'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, C), '
                                   'int64, int64)',
                                   3,
                                   36,
                                   0.595,
                                   0.595,
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
                                   35,
                                   8.402,
                                   5.381,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                   'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                   '1d, C), array(float64, 1d, C), float64, float64)',
                                   3,
                                   38,
                                   0.28,
                                   0.28,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                   'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, 1d, '
                                   'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                   3,
                                   38,
                                   1.37,
                                   0.252,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, C), '
                                   'float64, float64, float64, float64, array(int64, 1d, C))',
                                   4,
                                   40,
                                   1.118,
                                   1.118,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                   'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, C), '
                                   'array(int64, 1d, C), int64, float64, float64, float64)',
                                   3,
                                   38,
                                   0.324,
                                   0.324,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   38,
                                   0.735,
                                   0.735,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                   'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                   '2d, C), float64, float64, float64)',
                                   3,
                                   38,
                                   0.312,
                                   0.312,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.tips_touching',
                                   'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   1.75,
                                   1.75,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                   'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, bool)',
                                   2,
                                   35,
                                   0.216,
                                   0.216,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                   'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                   '1d, C), int64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   0.42,
                                   0.42,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.targeter_step',
                                   'bench_myriapoda.controllers.myriapod.targeter.targeter_step(array(float64, 2d, '
                                   'C), array(float64, 3d, C), array(bool, 1d, C), int64, array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C), float64, '
                                   'float64, float64, float64, array(float64, 2d, C), array(float64, 3d, C))',
                                   2,
                                   35,
                                   15.26,
                                   3.546,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                   'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                   'array(float64, 1d, C), float64, float64, float64)',
                                   3,
                                   48,
                                   9.771,
                                   8.601,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._other_normal',
                                   'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, 1d, '
                                   'C), float64, float64, float64)',
                                   4,
                                   49,
                                   1.169,
                                   0.606,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                   'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                   'float64, float64)',
                                   5,
                                   50,
                                   0.364,
                                   0.364,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                   'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), float64, '
                                   'float64, float64)',
                                   5,
                                   50,
                                   0.199,
                                   0.199,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                   'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64, float64)',
                                   3,
                                   48,
                                   1.051,
                                   0.439,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                   'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                   'float64, float64)',
                                   4,
                                   53,
                                   0.371,
                                   0.182,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                   'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                   'float64)',
                                   5,
                                   54,
                                   0.19,
                                   0.19,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                   'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                   '2d, C), int64, float64)',
                                   4,
                                   53,
                                   0.24,
                                   0.24,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                   'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, C), '
                                   'array(float64, 2d, C), float64, float64, float64, float64)',
                                   3,
                                   48,
                                   0.263,
                                   0.263,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                   'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, 2d, '
                                   'C))',
                                   3,
                                   48,
                                   0.63,
                                   0.63,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                   'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                   '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   2,
                                   35,
                                   9.535,
                                   1.655,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                   'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                   'float64, float64, float64, float64)',
                                   3,
                                   59,
                                   7.686,
                                   7.686,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                   'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   59,
                                   0.195,
                                   0.195,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                   'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, C), '
                                   'array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), array(bool, 1d, '
                                   'C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   2,
                                   35,
                                   2.154,
                                   1.144,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                   'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, int64)',
                                   3,
                                   62,
                                   0.107,
                                   0.107,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                   'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, int64)',
                                   3,
                                   62,
                                   0.143,
                                   0.143,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                   'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, C), '
                                   'int64, float64, float64, float64)',
                                   3,
                                   62,
                                   0.283,
                                   0.284,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                   'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                   3,
                                   62,
                                   0.161,
                                   0.161,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                   'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, 2d, '
                                   'C), int64, float64, float64, float64, float64)',
                                   3,
                                   62,
                                   0.315,
                                   0.315,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                   'array(bool, 1d, C))',
                                   2,
                                   35,
                                   8.234,
                                   1.967,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3), '
                                   'float64)',
                                   3,
                                   68,
                                   3.706,
                                   2.698,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                   'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, 1d, '
                                   'C), float64, float64, float64, float64)',
                                   4,
                                   69,
                                   1.008,
                                   1.008,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                   'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                   'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x 3))',
                                   3,
                                   68,
                                   2.561,
                                   2.561,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                   'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   35,
                                   1.191,
                                   0.698,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.leg_tip',
                                   'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), array(float64, '
                                   '2d, C), array(float64, 1d, C), float64, float64, float64, float64)',
                                   3,
                                   72,
                                   0.492,
                                   0.492,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                   '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                   2,
                                   35,
                                   1.992,
                                   1.992,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                   'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                   'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   2,
                                   35,
                                   6.139,
                                   5.175,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                   'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), float64, '
                                   'float64, float64)',
                                   3,
                                   75,
                                   0.265,
                                   0.265,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._wrap',
                                   'bench_myriapoda.kinematics.legs._wrap(float64)',
                                   3,
                                   75,
                                   0.142,
                                   0.142,
                                   False,
                                   True),
                                  ('bench_myriapoda.kinematics.legs._ik_solve',
                                   'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                   'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                   3,
                                   75,
                                   0.557,
                                   0.557,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                   'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                   '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, 1d, '
                                   'C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                   2,
                                   35,
                                   2.914,
                                   2.914,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                   'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), array(float64, '
                                   '3d, C), float64, array(float64, 1d, C))',
                                   2,
                                   34,
                                   3.1,
                                   1.484,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                   'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, 2d, '
                                   'C), array(float64, 1d, C))',
                                   3,
                                   80,
                                   1.616,
                                   1.616,
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
                                   52.094,
                                   22.811,
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
                                   0.488,
                                   0.488,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._edge_pass',
                                   'bench_myriapoda.bodies.fem.kernels._edge_pass(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   0.375,
                                   0.375,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_stress_pass',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_stress_pass(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   5.093,
                                   5.093,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rotation_fixup',
                                   'bench_myriapoda.bodies.fem.kernels._rotation_fixup(int64, array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   5.057,
                                   2.226,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._fcr_rotation',
                                   'bench_myriapoda.bodies.fem.kernels._fcr_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   86,
                                   2.832,
                                   1.15,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._svd3_core',
                                   'bench_myriapoda.bodies.fem.kernels._svd3_core(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   87,
                                   1.391,
                                   1.391,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels._rot_to_quat',
                                   'bench_myriapoda.bodies.fem.kernels._rot_to_quat(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   6,
                                   87,
                                   0.291,
                                   0.291,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity',
                                   'bench_myriapoda.bodies.fem.kernels.semi_implicit_velocity(array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), float64, array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(int64, 1d, C), array(float64, 1d, C), array(int64, '
                                   '1d, C), array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   4,
                                   82,
                                   2.983,
                                   0.744,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.skyline_solve',
                                   'bench_myriapoda.bodies.fem.kernels.skyline_solve(array(int64, 1d, C), '
                                   'array(int64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                   5,
                                   90,
                                   2.24,
                                   2.239,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                   'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                   'array(float64, 2d, C))',
                                   4,
                                   82,
                                   0.289,
                                   0.289,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                   'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, array(float64, '
                                   '1d, C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   82,
                                   0.616,
                                   0.616,
                                   False,
                                   True),
                                  ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                   'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                   'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                   'float64, float64)',
                                   4,
                                   82,
                                   0.639,
                                   0.639,
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
                                   13.741,
                                   3.665,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                   'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, 1d, '
                                   'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C))',
                                   4,
                                   95,
                                   0.423,
                                   0.32,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._cross',
                                   'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, float64, '
                                   'float64, float64)',
                                   5,
                                   96,
                                   0.104,
                                   0.104,
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
                                   9.653,
                                   7.632,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                   'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, 2d, '
                                   'C), float64, float64, float64, array(float64, 2d, C))',
                                   5,
                                   98,
                                   0.192,
                                   0.192,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                   'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, float64)',
                                   5,
                                   98,
                                   0.182,
                                   0.182,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                   'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, 2d, '
                                   'C), float64, float64, float64, float64, float64, float64, float64, float64, '
                                   'float64)',
                                   5,
                                   98,
                                   0.17,
                                   0.17,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   0.437,
                                   0.437,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                   'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   0.282,
                                   0.282,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                   'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64)',
                                   5,
                                   98,
                                   0.493,
                                   0.221,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                   'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                   'float64, float64, float64, float64, float64, float64, float64, float64, float64)',
                                   6,
                                   104,
                                   0.272,
                                   0.175,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                   'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, float64, '
                                   'float64, float64, float64, float64)',
                                   7,
                                   105,
                                   0.097,
                                   0.097,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                   'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                   'float64)',
                                   5,
                                   98,
                                   0.124,
                                   0.124,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                   'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, float64)',
                                   5,
                                   98,
                                   0.141,
                                   0.141,
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
                                   1.075,
                                   0.653,
                                   False,
                                   True),
                                  ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                   'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, 1d, '
                                   'C), float64, array(float64, 3d, C), array(float64, 3d, C), array(float64, 3d, '
                                   'C), array(float64, 4d, C))',
                                   2,
                                   109,
                                   0.423,
                                   0.423,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.tet_invariants',
                                   'bench_myriapoda.bodies.fem.kernels.tet_invariants(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.516,
                                   0.516,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.rigid_kernels.energy',
                                   'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                   'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                   'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                   'array(float64, 2d, C))',
                                   0,
                                   None,
                                   0.386,
                                   0.386,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.fem.kernels.elastic_energy',
                                   'bench_myriapoda.bodies.fem.kernels.elastic_energy(array(float64, 2d, C), '
                                   'array(int64, 2d, C), array(float64, 3d, C), array(float64, 1d, C), '
                                   'array(float64, 1d, C), array(float64, 1d, C))',
                                   0,
                                   None,
                                   0.445,
                                   0.445,
                                   False,
                                   True),
                                  ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                   'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                   'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                   0,
                                   None,
                                   0.604,
                                   0.604,
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
 'massspring-legged-dry': {'args': 'eNrtG11vI1fVTmwn2S7t0mppcbsry0JyWlmRu4lQ4Yk2cqXGmz4sRaSE1XQ8HvuO157xjmc28QMSqrQxSFcrwU4FBRVaPlSgoqV8vdEv9hHeeOEH8MYL/IFyzv2YD8/YTrLeUDXe0SZ3zv2Yc88599zzlW9nXln7cor9u+qt0s+bbreurmmWra85g57eX1PrfcdWNcejDykIUWxds0yAuZpj2d5tjy5pVm9g6y2P3h/vjC9o9gas4dHs07atDnDUct01Oo5hAjBn1ds6fO629/zQ+xaglG3gcI8skhx9JLZaX1M7qo2LPduxVJxGzoqJGVPt6oBeEzu+uIFfMZw9o+EQr/YVmlU0q6F7tcfcoXfFg8ENo+vV0jTXUQeWC9tNb3pyifMqIroqFioXnmyUC5uPe3KNbW+BLYIokhX5ffIAyZNHawvkMXKBXIytcYmvQQrb3xOzS0OYhEuco0vPmY7e0u3Qdsh5mjVM3Ad5GNDP9Y2WqTe875BHank+vwjfg8eBsZXghbdw6UkgbFYSXuCpSEAAEh28K5/8jC4TmTNhOd4lmvmx+IV6RqleAaqnBdUf4lRnhPP5BjR/RdC8Skr+k8S9xTHcW/dXui25x56ig62tgxBdSogjwIIvwZjKTbaLUrATaBVxugQX+TR/lyHCInsPOBdLQ3/CFjyRLfgnJy+lO+NLN7kwTrY3RmT7t3x/ATYliU2FHclHY0cSNICjGqbOTuULbq+jh09llh9+xLrK8G34JG+thvgxyg1xMJ6xrI6umtGDkakD1IOT8CDnRcD/B/nusD/M/p8Kprn+wxnkMgSKic8WG1H0x/P2FlFYL1CFZjXLNR2vViY7DN06XfmaaVjmC8iFEMKwT5cxDSdXgRm79CYbuBvHtpyoesqJyqScKKTlRAaXEw7GVY9c3X5bkGZ35x+LqRRj32rC2HIhGYVZgiN0OEHYNCzXj4v8sSj45GkGr98FB8asfS8l49gITNvZxiyIybF7HE/5OwvSZmA3Ddmr5YTSGgRqiryMSnqIuiCbSaW4ipprhLlGmGuET5dGmGhkxE2E3/kmwuVM1EQY870RKZ+rkLkKmauQT5kKmQWnmGnybiiYUqdnngcvtTHqRYJtgt23wi6VdByld1ZlvlxScGAhMTgQBGS+LzBAj6/IHO692jmaaxp6pwGeK01rHk1f9+jCDRsaex5duQbubld1DOjIEBgF4H34fwN8wqaxr8P7suo4St1qDGA0NjuWpnY8eqZjmNcUEzxtcJYzV/oYRVu4Uof2dafbg3bDAdeb3m+YfUc1NV3ROmofhn6hrpsaUboD21B7VkNdg6UN9L1hS4begC/t44pnN/n7M+z1NqrsejqVCkNXPzkq92irJuq9oyjDCN/vUknIDwoAE+TfhwQ5EuSIAVBcKywgUiU/EOGGEhO7++JWOY/34MAKCx28FA4dHCVOEKVVEk3YG7vy/yCvfPrvxPt+CsfEskcxEqYD7+XVFnKV/pjERhnG4lpmGMR+FkWoKmDYR8itAw/0TSWRU5cmGVuF7dfE5y/SZ6faTYeRfqbhfpIomh8FSrQoVOmWiFfeAUmMbcwPYzmI3u69C2ExQrzuE+Lj44jgDO/au9d+x7Q5Qhx8YxwHi0yTVIRffwf8+rhAQj8TyOIk1SEPf2H7Zz7lrYnG/uRTfhgdELcHCts/nyyrRT+2XmUX9pYIh3OpPZcktXxKlUntN4+rPZOjrPHz+wtJvJ1+eoyz9H8Q0fVZX7zHvDfXZ7GZ6frulzLcNS7UtUr+Rf5D/kneJ39ng3Z3NhIjXicg8+W5jJy4jJRP+Y1SPk1GXXk2dlSyWcOs5T/5AbIv+QGyU0XhwoxIXDjt57Jw0pdPYX77nPztMyEa9meuSg7Qblkgr9KsiOxkNaIaJsLfok+MCQZ11X6/37MNs7Um+zz6wFcZZBOnX9ZbIir0djaVGulYnUeJ7nWUSJ62+d0wvxvmd8P8bjjC3cAuh7+MizAXR/Ie3N99IlwyB3R4CktJl8ka1pA+zFd6ES6Zb5ALZFdWzuGwIDdydfs9PzdSjX3Djk/nYh9Mfz+UWlFY4HCvtpLgjrc/l06lWNGdQqrtz8ILi3W/HI8xXjpCjPGoBXHlOA2Yff+BHw3/2+Gy308dUpQThTOyz7uTzI1JoxmDPgyXe26xstQqqwPi8UQeOWQ1urLyVNaujq+PtHlVazFWvYsxuITXamIp8kg9bEV8HItZbXyGHpvoDgXqLg+Cyg/z2lUUuUh59LRa6WCPsermoB43z6exLE5+GJ2DBcE3fZSKvHx2fGVzVWQwXTbGZcW+SPKKJHkpGM2riEtBJbVcoCRiorg1V+5RVhvzvOoynKRYVnUHuvdqiyDX52W3FJLCfmGdCchfuYC0t/CARgkYvIpvsUHsB3a4QRW0M1r9LPsrvO4ZGRmUTLuMc6WIAJD8TZ8FJSaBod0jCjaSkE+RBHGlSLMi7eKBqB2/ddhU3Kur5HXyBs2ZStPWdY9muiwXm+FvK5jFVTCf69ElbnZD50rfMZpNU8eBSw212wMwTLH1vuPRXFPZs+xrcNrIW+0UkInex43wy7AKt8zpf0OQU5R1uxO62m6FUhci30bu1Bb9jPyUJPswIX9eHOMy2UbLaCjct6JnnnYcVSNd3WR/V3KR1gLATNJwbyZvcmIart0FOVklPyI/ZvUH5DUphmex5N4xVEGAs0TtNBV93wFk+9EShc8Y3Z7b6QMxYDM6ks+yNfidcyz7uquDOLZtPLiYsKBZv3bgIv34pHzBT3Di7VfjeBZLvHFO0aWWrd4wHJRJR7dtBRgBoprBNohY0zY0pQuao8MUCasg6ZFBf4QJX7fsToMzwWLtk83B/XqyoE7JwQlCZJsKHEoQt33+O7ev9Gx2bEEbGg0X62GyfVCQuqiBSV+BxnNYX6NZNgi3YjU9utjBo7moSjWKRTLXTPyBSzqq3dIdHKV2oyRc3rTgPkPti1TcuYFlMAIy92hOOh/3G7/8vCKv6PBlC+8HUcNi1PZK6AJwex+NEpjd/i7y/Yf4413mSIQto1LwJ0yRFaNKt+Tbv8G3KuJ/PknWI3+xxbaRl9ZkfooJOQE0BhhgPbbrUBYrs+6lwcu3o4SNJv8cczuzIq1Sfe1/2FoRNA==',
                           'case': 'centipede/massspring/walk',
                           'events': [('bench_myriapoda.bodies.rigid_kernels.box_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels.box_inertia(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.422,
                                       0.422,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.signed_distance',
                                       'bench_myriapoda.world.terrain_kernels.signed_distance(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       0,
                                       None,
                                       19.434,
                                       0.996,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_phi',
                                       'bench_myriapoda.world.terrain_kernels._other_phi(int64, array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       1,
                                       1,
                                       9.645,
                                       0.742,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_phi',
                                       'bench_myriapoda.world.terrain_kernels._slab_phi(array(float64, 1d, C), '
                                       'float64, float64)',
                                       2,
                                       2,
                                       0.165,
                                       0.166,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_phi',
                                       'bench_myriapoda.world.terrain_kernels._hf_phi(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       2,
                                       2,
                                       0.482,
                                       0.262,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.heightfield_height',
                                       'bench_myriapoda.world.terrain_kernels.heightfield_height(array(float64, 1d, '
                                       'C), float64, float64)',
                                       3,
                                       4,
                                       0.22,
                                       0.221,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._mesh_phi_normal',
                                       'bench_myriapoda.world.terrain_kernels._mesh_phi_normal(array(float64, 1d, '
                                       'C), float64, float64, float64)',
                                       2,
                                       2,
                                       8.256,
                                       0.632,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_query',
                                       'bench_myriapoda.world.terrain_kernels.mesh_query(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       6,
                                       7.624,
                                       1.56,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.mesh_exact',
                                       'bench_myriapoda.world.terrain_kernels.mesh_exact(array(float64, 1d, C), '
                                       'int64, float64, float64, float64, float64, int64)',
                                       4,
                                       7,
                                       6.064,
                                       1.991,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._candidate',
                                       'bench_myriapoda.world.terrain_kernels._candidate(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       1.28,
                                       0.72,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.closest_point_triangle',
                                       'bench_myriapoda.world.terrain_kernels.closest_point_triangle(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       6,
                                       9,
                                       0.56,
                                       0.56,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._descend',
                                       'bench_myriapoda.world.terrain_kernels._descend(array(float64, 1d, C), int64, '
                                       'float64, float64, float64, float64, float64, float64, float64, int64, int64)',
                                       5,
                                       8,
                                       0.976,
                                       0.976,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._cell_tris',
                                       'bench_myriapoda.world.terrain_kernels._cell_tris(array(float64, 1d, C), '
                                       'int64, int64, float64, float64, float64, float64, float64, float64, float64, '
                                       'int64, int64)',
                                       5,
                                       8,
                                       1.153,
                                       1.153,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._pseudo_normal',
                                       'bench_myriapoda.world.terrain_kernels._pseudo_normal(array(float64, 1d, C), '
                                       'int64, int64, int64)',
                                       5,
                                       8,
                                       0.663,
                                       0.663,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._min_obstacles',
                                       'bench_myriapoda.world.terrain_kernels._min_obstacles(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       1,
                                       1,
                                       8.792,
                                       7.186,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_phi',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_phi(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       2,
                                       14,
                                       0.578,
                                       0.578,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below_brute',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below_brute(array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       2,
                                       14,
                                       1.029,
                                       1.029,
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
                                       2.174,
                                       1.518,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.quat_to_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels.quat_to_matrix(array(float64, 2d, C), '
                                       'array(float64, 3d, C))',
                                       1,
                                       17,
                                       0.656,
                                       0.234,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._rotation_matrix',
                                       'bench_myriapoda.bodies.rigid_kernels._rotation_matrix(float64, float64, '
                                       'float64, float64, array(float64, 2d, C))',
                                       2,
                                       18,
                                       0.421,
                                       0.421,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.legs_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.legs_forward_kinematics(array(float64, 2d, '
                                       'C), array(float64, 3d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C))',
                                       0,
                                       None,
                                       1.989,
                                       0.543,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.side_sign',
                                       'bench_myriapoda.kinematics.legs.side_sign(int64)',
                                       1,
                                       20,
                                       0.102,
                                       0.102,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_forward_kinematics',
                                       'bench_myriapoda.kinematics.legs.leg_forward_kinematics(array(float64, 1d, '
                                       'C), array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64, array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, '
                                       'C))',
                                       1,
                                       20,
                                       1.345,
                                       0.577,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_root',
                                       'bench_myriapoda.kinematics.legs.leg_root(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), array(float64, 1d, C))',
                                       2,
                                       22,
                                       0.542,
                                       0.286,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.matvec',
                                       'bench_myriapoda.kinematics.rotations.matvec(array(float64, 2d, C), float64, '
                                       'float64, float64)',
                                       3,
                                       23,
                                       0.257,
                                       0.257,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_plane_points',
                                       'bench_myriapoda.kinematics.legs.leg_plane_points(float64, float64, float64, '
                                       'float64, float64)',
                                       2,
                                       22,
                                       0.225,
                                       0.225,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.target_pose',
                                       'bench_myriapoda.controllers.myriapod.switcher.target_pose(int64, '
                                       'array(float64, 1d, C))',
                                       0,
                                       None,
                                       0.424,
                                       0.424,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.wave_angles',
                                       'bench_myriapoda.controllers.myriapod.antennae.wave_angles(array(float64, 1d, '
                                       'C), float64, array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.374,
                                       0.374,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_forward_kinematics(array(float64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 1d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       0,
                                       None,
                                       1.405,
                                       0.958,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame',
                                       'bench_myriapoda.controllers.myriapod.antennae._yaw_pitch_frame(array(float64, '
                                       '2d, C), float64, float64, array(float64, 2d, C))',
                                       1,
                                       28,
                                       0.447,
                                       0.447,
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
                                       109.879,
                                       13.819,
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
                                       61.26,
                                       4.743,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled.numpy_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled.numpy_sum(array(float64, 1d, '
                                       'C), int64)',
                                       2,
                                       31,
                                       2.472,
                                       1.736,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._block_sum',
                                       'bench_myriapoda.controllers.myriapod.compiled._block_sum(array(float64, 1d, '
                                       'C), int64, int64)',
                                       3,
                                       32,
                                       0.738,
                                       0.738,
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
                                       31,
                                       9.776,
                                       6.34,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._root_toward_target',
                                       'bench_myriapoda.controllers.myriapod.antennae._root_toward_target(array(float64, '
                                       '1d, C), array(float64, 1d, C), float64, float64)',
                                       3,
                                       34,
                                       0.262,
                                       0.262,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._near_obstacles',
                                       'bench_myriapoda.controllers.myriapod.antennae._near_obstacles(array(float64, '
                                       '1d, C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       3,
                                       34,
                                       1.377,
                                       0.256,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_within',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_within(array(float64, 1d, '
                                       'C), float64, float64, float64, float64, array(int64, 1d, C))',
                                       4,
                                       36,
                                       1.122,
                                       1.122,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._phi_near',
                                       'bench_myriapoda.controllers.myriapod.antennae._phi_near(array(float64, 1d, '
                                       'C), array(int64, 1d, C), int64, float64, float64, float64)',
                                       3,
                                       34,
                                       0.266,
                                       0.266,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_normal(array(float64, 1d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       34,
                                       1.043,
                                       1.043,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae._angles_of_direction',
                                       'bench_myriapoda.controllers.myriapod.antennae._angles_of_direction(array(float64, '
                                       '2d, C), float64, float64, float64)',
                                       3,
                                       34,
                                       0.488,
                                       0.488,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.tips_touching',
                                       'bench_myriapoda.kinematics.legs.tips_touching(int64, array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       1.244,
                                       1.244,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.compiled._avoidance_turn',
                                       'bench_myriapoda.controllers.myriapod.compiled._avoidance_turn(bool, bool, '
                                       'bool)',
                                       2,
                                       31,
                                       0.213,
                                       0.213,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.segments_supported',
                                       'bench_myriapoda.controllers.myriapod.targeter.segments_supported(array(int64, '
                                       '1d, C), int64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       0.366,
                                       0.366,
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
                                       15.523,
                                       3.111,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal',
                                       'bench_myriapoda.world.terrain_kernels._obstacle_or_base_normal(int64, '
                                       'array(float64, 1d, C), float64, float64, float64)',
                                       3,
                                       44,
                                       10.375,
                                       8.909,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._other_normal',
                                       'bench_myriapoda.world.terrain_kernels._other_normal(int64, array(float64, '
                                       '1d, C), float64, float64, float64)',
                                       4,
                                       45,
                                       1.465,
                                       0.622,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._slab_normal',
                                       'bench_myriapoda.world.terrain_kernels._slab_normal(array(float64, 1d, C), '
                                       'float64, float64)',
                                       5,
                                       46,
                                       0.466,
                                       0.466,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._hf_normal',
                                       'bench_myriapoda.world.terrain_kernels._hf_normal(array(float64, 1d, C), '
                                       'float64, float64, float64)',
                                       5,
                                       46,
                                       0.378,
                                       0.378,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.balance',
                                       'bench_myriapoda.controllers.myriapod.targeter.balance(array(float64, 1d, C), '
                                       'array(float64, 2d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64)',
                                       3,
                                       44,
                                       1.066,
                                       0.473,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.turn_toward',
                                       'bench_myriapoda.controllers.myriapod.targeter.turn_toward(float64, float64, '
                                       'float64, float64)',
                                       4,
                                       49,
                                       0.328,
                                       0.155,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.limited_turn',
                                       'bench_myriapoda.controllers.myriapod.targeter.limited_turn(float64, float64, '
                                       'float64)',
                                       5,
                                       50,
                                       0.173,
                                       0.173,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis',
                                       'bench_myriapoda.controllers.myriapod.targeter.rotate_about_own_axis(array(float64, '
                                       '2d, C), int64, float64)',
                                       4,
                                       49,
                                       0.265,
                                       0.265,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.head_motion',
                                       'bench_myriapoda.controllers.myriapod.targeter.head_motion(array(float64, 1d, '
                                       'C), array(float64, 2d, C), float64, float64, float64, float64)',
                                       3,
                                       44,
                                       0.279,
                                       0.279,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.orthonormalize',
                                       'bench_myriapoda.controllers.myriapod.targeter.orthonormalize(array(float64, '
                                       '2d, C))',
                                       3,
                                       44,
                                       0.693,
                                       0.693,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls',
                                       'bench_myriapoda.controllers.myriapod.targeter.keep_clear_of_walls(array(float64, '
                                       '2d, C), array(float64, 3d, C), array(bool, 1d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       2,
                                       31,
                                       8.577,
                                       1.914,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacles_below',
                                       'bench_myriapoda.world.terrain_kernels.obstacles_below(array(float64, 1d, C), '
                                       'float64, float64, float64, float64)',
                                       3,
                                       55,
                                       6.41,
                                       6.41,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.obstacle_normal',
                                       'bench_myriapoda.world.terrain_kernels.obstacle_normal(array(float64, 1d, C), '
                                       'int64, float64, float64, float64)',
                                       3,
                                       55,
                                       0.253,
                                       0.253,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.switcher_step',
                                       'bench_myriapoda.controllers.myriapod.switcher.switcher_step(array(int64, 1d, '
                                       'C), array(float64, 2d, C), array(bool, 1d, C), array(bool, 1d, C), '
                                       'array(bool, 1d, C), array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       2,
                                       31,
                                       2.514,
                                       1.379,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.first_wave_segment',
                                       'bench_myriapoda.controllers.myriapod.switcher.first_wave_segment(int64, '
                                       'int64)',
                                       3,
                                       58,
                                       0.139,
                                       0.139,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.previous_leg',
                                       'bench_myriapoda.controllers.myriapod.switcher.previous_leg(int64, int64, '
                                       'int64)',
                                       3,
                                       58,
                                       0.183,
                                       0.183,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._pose_error',
                                       'bench_myriapoda.controllers.myriapod.switcher._pose_error(array(float64, 2d, '
                                       'C), int64, float64, float64, float64)',
                                       3,
                                       58,
                                       0.307,
                                       0.307,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.state_after_target',
                                       'bench_myriapoda.controllers.myriapod.switcher.state_after_target(int64)',
                                       3,
                                       58,
                                       0.164,
                                       0.164,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher._move_toward',
                                       'bench_myriapoda.controllers.myriapod.switcher._move_toward(array(float64, '
                                       '2d, C), int64, float64, float64, float64, float64)',
                                       3,
                                       58,
                                       0.342,
                                       0.342,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.stop_swinging_legs(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(float64, 2d, C), int64, array(float64, 1d, C), '
                                       'array(bool, 1d, C))',
                                       2,
                                       31,
                                       8.428,
                                       1.895,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_at',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_at(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3), float64)',
                                       3,
                                       64,
                                       4.901,
                                       3.6,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels._phi_at_least',
                                       'bench_myriapoda.world.terrain_kernels._phi_at_least(int64, array(float64, '
                                       '1d, C), float64, float64, float64, float64)',
                                       4,
                                       65,
                                       1.301,
                                       1.301,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision._clear_edge',
                                       'bench_myriapoda.controllers.myriapod.leg_collision._clear_edge(int64, '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), float64, UniTuple(float64 x 3), UniTuple(float64 x '
                                       '3))',
                                       3,
                                       64,
                                       1.631,
                                       1.631,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips',
                                       'bench_myriapoda.controllers.myriapod.switcher.fix_stance_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       31,
                                       0.482,
                                       0.304,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.leg_tip',
                                       'bench_myriapoda.kinematics.legs.leg_tip(array(float64, 1d, C), '
                                       'array(float64, 2d, C), array(float64, 1d, C), float64, float64, float64, '
                                       'float64)',
                                       3,
                                       68,
                                       0.178,
                                       0.178,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.surface_touchdown_tips(array(bool, '
                                       '1d, C), array(float64, 2d, C), int64, array(float64, 1d, C))',
                                       2,
                                       31,
                                       1.307,
                                       1.307,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs.stance_ik_and_fk',
                                       'bench_myriapoda.kinematics.legs.stance_ik_and_fk(array(int64, 1d, C), int64, '
                                       'array(float64, 2d, C), array(float64, 3d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(bool, 1d, C), float64, '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       2,
                                       31,
                                       4.146,
                                       3.57,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.rotations.mat_t_vec',
                                       'bench_myriapoda.kinematics.rotations.mat_t_vec(array(float64, 2d, C), '
                                       'float64, float64, float64)',
                                       3,
                                       71,
                                       0.201,
                                       0.201,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._wrap',
                                       'bench_myriapoda.kinematics.legs._wrap(float64)',
                                       3,
                                       71,
                                       0.073,
                                       0.073,
                                       False,
                                       True),
                                      ('bench_myriapoda.kinematics.legs._ik_solve',
                                       'bench_myriapoda.kinematics.legs._ik_solve(float64, float64, float64, '
                                       'array(float64, 2d, C), float64, array(float64, 1d, C), float64)',
                                       3,
                                       71,
                                       0.301,
                                       0.301,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration',
                                       'bench_myriapoda.controllers.myriapod.leg_collision.knees_inside_and_penetration(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), int64, array(float64, '
                                       '1d, C), bool, array(bool, 1d, C), array(float64, 1d, C))',
                                       2,
                                       31,
                                       1.469,
                                       1.469,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.drive_to_targets',
                                       'bench_myriapoda.bodies.kinematic_targets.drive_to_targets(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), array(bool, 1d, C), array(float64, 2d, C), '
                                       'array(float64, 3d, C), float64, array(float64, 1d, C))',
                                       2,
                                       30,
                                       1.535,
                                       0.711,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion',
                                       'bench_myriapoda.bodies.kinematic_targets.matrix_to_quaternion(array(float64, '
                                       '2d, C), array(float64, 1d, C))',
                                       3,
                                       76,
                                       0.824,
                                       0.824,
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
                                       32.222,
                                       17.163,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.massspring.kernels.spring_forces',
                                       'bench_myriapoda.bodies.massspring.kernels.spring_forces(array(float64, 2d, '
                                       'C), array(float64, 2d, C), array(int64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 1d, C), array(float64, 1d, C), array(float64, 2d, C))',
                                       4,
                                       78,
                                       0.325,
                                       0.325,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_chain.link_spines',
                                       'bench_myriapoda.bodies.rigid_chain.link_spines(array(float64, 2d, C), '
                                       'array(float64, 2d, C))',
                                       4,
                                       78,
                                       0.223,
                                       0.223,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.friction_kernels.ground_friction',
                                       'bench_myriapoda.bodies.friction_kernels.ground_friction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64, float64, float64)',
                                       4,
                                       78,
                                       0.595,
                                       0.595,
                                       False,
                                       True),
                                      ('bench_myriapoda.world.terrain_kernels.path_surface_fraction',
                                       'bench_myriapoda.world.terrain_kernels.path_surface_fraction(int64, '
                                       'array(float64, 1d, C), float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       4,
                                       78,
                                       0.726,
                                       0.726,
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
                                       13.188,
                                       4.225,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces',
                                       'bench_myriapoda.bodies.rigid_kernels.accumulate_point_forces(array(int64, '
                                       '1d, C), array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C))',
                                       4,
                                       83,
                                       0.431,
                                       0.327,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._cross',
                                       'bench_myriapoda.bodies.rigid_kernels._cross(float64, float64, float64, '
                                       'float64, float64, float64)',
                                       5,
                                       84,
                                       0.104,
                                       0.104,
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
                                       8.532,
                                       6.327,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia',
                                       'bench_myriapoda.bodies.rigid_kernels._world_inverse_inertia(array(float64, '
                                       '2d, C), float64, float64, float64, array(float64, 2d, C))',
                                       5,
                                       86,
                                       0.203,
                                       0.203,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._tangent_basis',
                                       'bench_myriapoda.bodies.rigid_kernels._tangent_basis(float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.215,
                                       0.215,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._inv_mass_along',
                                       'bench_myriapoda.bodies.rigid_kernels._inv_mass_along(float64, array(float64, '
                                       '2d, C), float64, float64, float64, float64, float64, float64, float64, '
                                       'float64, float64)',
                                       5,
                                       86,
                                       0.272,
                                       0.272,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._hu_friction_impulse(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64)',
                                       5,
                                       86,
                                       0.495,
                                       0.495,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse',
                                       'bench_myriapoda.bodies.rigid_kernels._coulomb_friction_impulse(float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64)',
                                       5,
                                       86,
                                       0.282,
                                       0.282,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._free_rotation',
                                       'bench_myriapoda.bodies.rigid_kernels._free_rotation(float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.481,
                                       0.217,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._axis_flow',
                                       'bench_myriapoda.bodies.rigid_kernels._axis_flow(int64, float64, float64, '
                                       'float64, float64, float64, float64, float64, float64, float64, float64, '
                                       'float64)',
                                       6,
                                       92,
                                       0.264,
                                       0.173,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qmul',
                                       'bench_myriapoda.bodies.rigid_kernels._qmul(float64, float64, float64, '
                                       'float64, float64, float64, float64, float64)',
                                       7,
                                       93,
                                       0.091,
                                       0.091,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._qnormalize',
                                       'bench_myriapoda.bodies.rigid_kernels._qnormalize(float64, float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.123,
                                       0.123,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels._q_from_rotvec',
                                       'bench_myriapoda.bodies.rigid_kernels._q_from_rotvec(float64, float64, '
                                       'float64)',
                                       5,
                                       86,
                                       0.134,
                                       0.134,
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
                                       1.043,
                                       0.625,
                                       False,
                                       True),
                                      ('bench_myriapoda.controllers.myriapod.antennae.antennae_links',
                                       'bench_myriapoda.controllers.myriapod.antennae.antennae_links(array(float64, '
                                       '1d, C), float64, array(float64, 3d, C), array(float64, 3d, C), '
                                       'array(float64, 3d, C), array(float64, 4d, C))',
                                       2,
                                       97,
                                       0.417,
                                       0.417,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.rigid_kernels.energy',
                                       'bench_myriapoda.bodies.rigid_kernels.energy(array(float64, 2d, C), '
                                       'array(float64, 2d, C), array(float64, 2d, C), array(float64, 2d, C), '
                                       'array(float64, 1d, C), array(float64, 2d, C), array(float64, 1d, C), '
                                       'array(float64, 2d, C))',
                                       0,
                                       None,
                                       0.39,
                                       0.39,
                                       False,
                                       True),
                                      ('bench_myriapoda.bodies.segment_frames.groups_touching',
                                       'bench_myriapoda.bodies.segment_frames.groups_touching(array(float64, 2d, C), '
                                       'int64, int64, array(float64, 1d, C), float64, array(bool, 1d, C))',
                                       0,
                                       None,
                                       0.555,
                                       0.555,
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
