MODULE raise_new_number_in_handler
  ! Tests: RAISE n in a handler replaces the error: the caller sees ERRNO n,
  ! not the original error.
  CONST errnum ERR_SENSOR := 12;
  PROC readSensor()
    VAR num raw := 0;
    raw := 100 / raw;
  ERROR
    RAISE ERR_SENSOR;
  ENDPROC
  PROC main()
    readSensor;
  ERROR
    IF ERRNO = ERR_SENSOR TPWrite "sensor error";
    IF ERRNO = ERR_DIVZERO TPWrite "division error";
    RETURN;
  ENDPROC
ENDMODULE
