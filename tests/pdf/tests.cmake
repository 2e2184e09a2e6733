# The PDF calculation package (label "pdf", docs/pdf.md): every page
# rendered by pdftoppm and read by pdftotext. Skips (77) without
# poppler-utils.
rb_script_test(NAME pdf_package SCRIPT tests/pdf/pdf.py LABEL pdf)
# fontconfig and pango keep their font state to the end of the process:
# not leaks of rockbolt's (lsan.supp)
if(TEST pdf_package)
  set_tests_properties(pdf_package PROPERTIES SKIP_RETURN_CODE 77
      ENVIRONMENT "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/pdf/lsan.supp")
endif()
