MODULE num_float32_large_integer
  ! Tests: num has a 24-bit mantissa: 16777216 + 1 rounds back to 16777216,
  ! and 8388608 + 0.5 rounds to 8388608 (exact integers only up to 2^23).
  PROC main()
    VAR num big := 16777216;
    VAR num half := 8388608;
    big := big + 1;
    TPWrite "big unchanged " \Bool:=big = 16777216;
    half := half + 0.5;
    TPWrite "half lost " \Bool:=half = 8388608;
  ENDPROC
ENDMODULE
