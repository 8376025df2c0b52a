MODULE MainModule
  ! Tests: Set takes a signaldo; a num variable is a static type error.
  PROC main()
    VAR num n;
    TPWrite "must not run";
    Set n;
  ENDPROC
ENDMODULE
