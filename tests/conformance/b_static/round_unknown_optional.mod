MODULE MainModule
  ! Tests: Round's optional parameter is \Dec; another name is a static argument error.
  PROC main()
    VAR num x;
    TPWrite "must not run";
    x := Round(1.25 \Decimals:=1);
  ENDPROC
ENDMODULE
