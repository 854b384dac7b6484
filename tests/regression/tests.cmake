# vpsolve executable tests (bad input, short case runs); included from tests/CMakeLists.txt.

# --- Particles (DEM) -------------------------------------------------------------------------
set(VP_DEM_DATA ${CMAKE_CURRENT_SOURCE_DIR}/regression/data)
set(VP_EXPECT_ERROR ${CMAKE_CURRENT_SOURCE_DIR}/regression/expect_error.sh)

# MPI particle tests on 4 ranks as well (migration, ghosts, rank invariance).
add_test(NAME mpi_np4_particles
         COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 4 --oversubscribe $<TARGET_FILE:vp_tests> "[mpi]")
set_tests_properties(mpi_np4_particles PROPERTIES ENVIRONMENT "${VP_MPI_ENV}" PROCESSORS 4)

# Bad particle input: a clear message and a non-zero exit.
foreach(bad
    "overlap|overlap by"
    "outside|outside the domain"
    "radius_zero|radius must be > 0"
    "density_negative|density must be > 0"
    "missing_column|lacks column\\(s\\) wz"
    "nan|column y is not a finite number"
    "duplicate|duplicate particle id 3")
  string(REPLACE "|" ";" parts "${bad}")
  list(GET parts 0 name)
  list(GET parts 1 pattern)
  add_test(NAME dem_bad_input_${name}
           COMMAND ${VP_EXPECT_ERROR} "${pattern}"
                   $<TARGET_FILE:vpsolve> -options_file ${VP_DEM_DATA}/box.opts
                   -particles_file ${VP_DEM_DATA}/${name}.csv -output_dir dem_bad_${name})
  set_tests_properties(dem_bad_input_${name} PROPERTIES ENVIRONMENT "${VP_MPI_ENV}")
endforeach()

add_test(NAME dem_bad_option_restitution
         COMMAND ${VP_EXPECT_ERROR} "-contact_restitution: must be in \\(0, 1\\]"
                 $<TARGET_FILE:vpsolve> -options_file ${VP_DEM_DATA}/box.opts
                 -particles_file ${VP_DEM_DATA}/good.csv -contact_restitution 1.5)
add_test(NAME dem_bad_option_no_stiffness
         COMMAND ${VP_EXPECT_ERROR} "needs? a contact stiffness"
                 $<TARGET_FILE:vpsolve> -options_file ${VP_DEM_DATA}/box.opts
                 -particles_file ${VP_DEM_DATA}/good.csv -contact_tc 0)
add_test(NAME dem_bad_missing_file
         COMMAND ${VP_EXPECT_ERROR} "cannot open"
                 $<TARGET_FILE:vpsolve> -options_file ${VP_DEM_DATA}/box.opts
                 -particles_file ${VP_DEM_DATA}/no_such_file.csv)
# A subdomain thinner than the particle halo (2 ranks on a 4 mm box, 2 mm spheres).
add_test(NAME dem_bad_thin_subdomain
         COMMAND ${VP_EXPECT_ERROR} "thinner than the particle halo"
                 ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 --oversubscribe $<TARGET_FILE:vpsolve>
                 -options_file ${VP_DEM_DATA}/box.opts -grid_n 2,1,1 -grid_hi 0.004,0.04,0.04
                 -particle_position 0.002,0.02,0.02 -particle_radius 0.001)
set_tests_properties(dem_bad_option_restitution dem_bad_option_no_stiffness dem_bad_missing_file
                     dem_bad_thin_subdomain PROPERTIES ENVIRONMENT "${VP_MPI_ENV}")

# The dry collapse case, shortened, on 2 ranks: it runs and writes the contracted outputs.
add_test(NAME dem_case_granular_collapse_dry
         COMMAND sh -c "rm -rf dem_collapse && ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 --oversubscribe \
                 $<TARGET_FILE:vpsolve> -options_file ${PROJECT_SOURCE_DIR}/cases/granular_collapse_dry.opts \
                 -particles_file ${PROJECT_SOURCE_DIR}/cases/data/column_2000.csv -time_final 0.0036 \
                 -output_dt 0 -output_every 500 -output_dir dem_collapse \
                 && test -f dem_collapse/particles_000000.h5 && test -f dem_collapse/particles_001000.h5 \
                 && grep -q particles_001000.h5 dem_collapse/particles.xmf \
                 && test $(wc -l < dem_collapse/diagnostics.csv) -eq 1001 \
                 && test $(wc -l < dem_collapse/particle_1000.csv) -eq 1002")
set_tests_properties(dem_case_granular_collapse_dry PROPERTIES ENVIRONMENT "${VP_MPI_ENV}" PROCESSORS 2)
