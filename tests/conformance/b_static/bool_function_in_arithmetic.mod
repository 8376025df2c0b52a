MODULE MainModule
  ! Tests: TestDI returns bool; adding it to a num is a static type error.
  VAR signaldi diA;
  PROC main()
    VAR num n;
    TPWrite "must not run";
    n := TestDI(diA) + 1;
  ENDPROC
ENDMODULE
