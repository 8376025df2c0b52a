MODULE MainModule
  ! Tests: a misspelt predefined function (Sqr for Sqrt) is an unknown routine.
  PROC main()
    VAR num x;
    TPWrite "must not run";
    x := Sqr(4);
  ENDPROC
ENDMODULE
