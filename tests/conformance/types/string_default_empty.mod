MODULE string_default_empty
  ! Tests: an uninitialised string variable is the empty string.
  PROC main()
    VAR string s;
    TPWrite "[" + s + "]";
    TPWrite "empty " \Bool:=s = "";
  ENDPROC
ENDMODULE
