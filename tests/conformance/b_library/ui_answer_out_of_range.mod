MODULE MainModule
  ! Tests: an answer the dialog cannot give (a number outside \MinValue..\MaxValue) is bad
  ! input in run, reported with RMC303 and exit code 2.
  VAR num nSpeed;
  PROC main()
    nSpeed := UINumEntry(\Header:="Speed" \Message:="Override in %" \MinValue:=10 \MaxValue:=100);
    TPWrite "speed " \Num:=nSpeed;
  ENDPROC
ENDMODULE
