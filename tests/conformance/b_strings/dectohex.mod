MODULE MainModule
  ! Tests: DecToHex converts a decimal digit string to upper-case hexadecimal.
  PROC main()
    TPWrite DecToHex("99999999");
    TPWrite DecToHex("255");
    TPWrite DecToHex("0");
    TPWrite DecToHex("4294967296");
  ENDPROC
ENDMODULE
