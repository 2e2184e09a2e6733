# Figures (label "plot"): plot_sample writes the SVG figures and the HTML
# page of a case; a real XML parser must accept every file, and a headless
# Chromium must render the page without console errors to a picture that
# is not blank. Both skip (77) when python3 or chromium is not installed.
add_executable(plot_sample ${PROJECT_SOURCE_DIR}/tests/plot/plot_sample.c)
rb_target_defaults(plot_sample)
target_link_libraries(plot_sample PRIVATE rb_all)

add_test(NAME plot_wellformed
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/plot/check_xml.sh
                 $<TARGET_FILE:plot_sample> ${CMAKE_CURRENT_BINARY_DIR}/plot-scratch/xml)
add_test(NAME plot_chromium
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/plot/render_html.sh
                 $<TARGET_FILE:plot_sample> ${CMAKE_CURRENT_BINARY_DIR}/plot-scratch/chromium)
set_tests_properties(plot_wellformed plot_chromium PROPERTIES LABELS plot
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} SKIP_RETURN_CODE 77 TIMEOUT 300)
