# The PDF calculation package (label "pdf", docs/pdf.md): every page
# rendered by pdftoppm and read by pdftotext. Skips (77) without
# poppler-utils.
rb_script_test(NAME pdf_package SCRIPT tests/pdf/pdf.py LABEL pdf)
set_tests_properties(pdf_package PROPERTIES SKIP_RETURN_CODE 77)
