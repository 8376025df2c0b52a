MODULE WeldMain
  ! Tests: data passed only to a routine of a module not given takes the num the stubs
  ! assume for the routine's parameters, said so in both comments, so the written module
  ! loads (issue 28; issue 8 left p10, p20 and seamA undeclared). untyped_copy keeps a
  ! name whose type nothing tells.
  PROC main()
    WeldSeam p10, p20, seamA;
    nSeams := nSeams + 1;
  ENDPROC
ENDMODULE
