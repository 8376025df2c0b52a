MODULE retry_several_times
  ! Tests: RETRY may be used repeatedly (twice here, under the documented
  ! default retry limit of 4); each retry re-executes the failing statement.
  VAR num attempts := 0;
  PROC main()
    VAR num d := 0;
    VAR num x;
    x := 12 / d;
    TPWrite "attempts=" \Num:=attempts;
    TPWrite "x=" \Num:=x;
  ERROR
    attempts := attempts + 1;
    IF attempts = 2 d := 3;
    RETRY;
  ENDPROC
ENDMODULE
