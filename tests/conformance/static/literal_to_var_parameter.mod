MODULE literal_to_var_parameter
  ! Tests: a VAR parameter needs a data reference; passing a literal is a
  ! static error (RMC208).
  PROC bump(VAR num v)
    v := v + 1;
  ENDPROC
  PROC main()
    TPWrite "never printed";
    bump 5;  ! <-- error
  ENDPROC
ENDMODULE
