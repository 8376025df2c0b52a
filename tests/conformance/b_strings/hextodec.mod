MODULE MainModule
  ! Tests: HexToDec converts a hexadecimal string (upper or lower case digits) to decimal.
  PROC main()
    TPWrite HexToDec("5F5E0FF");
    TPWrite HexToDec("FF");
    TPWrite HexToDec("ff");
    TPWrite HexToDec("100000000");
  ENDPROC
ENDMODULE
