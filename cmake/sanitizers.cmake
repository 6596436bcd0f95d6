# ASan + UBSan for the `asan` preset. Applied globally so that every library and
# test of the build is instrumented the same way.
if(FW_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
