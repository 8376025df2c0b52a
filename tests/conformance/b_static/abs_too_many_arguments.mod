MODULE MainModule
  ! Tests: calling Abs with two arguments is a static error (exit 2, nothing runs).
  PROC main()
    VAR num x;
    TPWrite "must not run";
    x := Abs(1, 2);
  ENDPROC
ENDMODULE
