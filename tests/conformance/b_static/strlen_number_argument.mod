MODULE MainModule
  ! Tests: StrLen takes a string; a num argument is a static type error.
  PROC main()
    VAR num n;
    TPWrite "must not run";
    n := StrLen(5);
  ENDPROC
ENDMODULE
