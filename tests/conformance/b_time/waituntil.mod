MODULE MainModule
  ! Tests: WaitUntil continues at once when its condition is already TRUE.
  PROC main()
    VAR num n := 5;
    WaitUntil n > 3;
    TPWrite "n > 3 passed";
    WaitUntil TRUE;
    TPWrite "TRUE passed";
  ENDPROC
ENDMODULE
