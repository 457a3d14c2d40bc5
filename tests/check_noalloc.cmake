cmake_minimum_required(VERSION 3.18)
# Fails if the archive LIB references a heap or stdio function.
# Usage: cmake -DNM=nm -DLIB=libringloc_core.a [-DALLOW=snprintf,vsnprintf] -P check_noalloc.cmake
if(NOT NM OR NOT LIB)
  message(FATAL_ERROR "usage: cmake -DNM=nm -DLIB=lib.a -P check_noalloc.cmake")
endif()
execute_process(COMMAND ${NM} -u ${LIB} OUTPUT_VARIABLE undefined
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} -u ${LIB} failed: ${err}")
endif()
set(forbidden
  malloc calloc realloc free aligned_alloc posix_memalign memalign valloc strdup strndup
  printf fprintf sprintf snprintf vprintf vfprintf vsprintf vsnprintf dprintf
  puts fputs putchar fputc putc fwrite fread fgets fgetc getc getchar gets
  scanf fscanf sscanf fopen fdopen freopen fclose fflush fseek ftell rewind
  perror setvbuf setbuf stdin stdout stderr tmpfile)
# ALLOW: names this archive may use (the firmware loop formats log lines)
if(ALLOW)
  string(REPLACE "," ";" allow "${ALLOW}")
  list(REMOVE_ITEM forbidden ${allow})
endif()
string(REPLACE "\n" ";" lines "${undefined}")
set(found "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "^[ \t]*U[ \t]+" "" sym "${line}")
  string(REGEX REPLACE "@.*$" "" sym "${sym}")       # versioned symbols
  string(REGEX REPLACE "^__(.*)_chk$" "\\1" sym "${sym}")  # fortified variants
  string(REGEX REPLACE "^__isoc99_" "" sym "${sym}")
  if(sym IN_LIST forbidden)
    list(APPEND found ${sym})
  endif()
endforeach()
list(REMOVE_DUPLICATES found)
if(found)
  message(FATAL_ERROR "${LIB} references heap or stdio functions: ${found}")
endif()
message(STATUS "${LIB} references no heap or stdio function")
