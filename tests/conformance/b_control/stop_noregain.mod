MODULE MainModule
  ! Tests: Stop \NoRegain inside a called routine halts the program (exit code 0).
  PROC main()
    Sub;
    TPWrite "not reached";
  ENDPROC

  PROC Sub()
    TPWrite "in Sub";
    Stop \NoRegain;
    TPWrite "not reached in Sub";
  ENDPROC
ENDMODULE
