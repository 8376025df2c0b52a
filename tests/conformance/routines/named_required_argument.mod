MODULE named_required_argument
  ! Tests: a required argument may be written with its parameter name
  ! (Name:=value), in parameter order.
  PROC show(num Val, string Unit)
    TPWrite Unit \Num:=Val;
  ENDPROC
  PROC main()
    show Val:=5, Unit:="mm=";
    show 6, Unit:="cm=";
  ENDPROC
ENDMODULE
