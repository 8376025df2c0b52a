MODULE retry_repeats_call
  ! Tests: RETRY in the caller's handler re-executes the call statement that
  ! failed (the callee runs again from its start).
  VAR num calls := 0;
  PROC flaky()
    calls := calls + 1;
    TPWrite "call " \Num:=calls;
    IF calls = 1 RAISE 3;
    TPWrite "flaky ok";
  ENDPROC
  PROC main()
    flaky;
    TPWrite "done";
  ERROR
    RETRY;
  ENDPROC
ENDMODULE
