MODULE prog
    ! Written for the test (issue 28): a PLC sets bStart; the robot runs one cycle each time.
    ! The property names bStart, and the program still reads what the PLC may write.
    PERS bool bStart := FALSE;
    VAR num cycles := 0;
    VAR bool running := FALSE;

    PROC main()
        WHILE TRUE DO
            WaitUntil bStart;
            running := TRUE;
            cycles := cycles + 1;
            IF cycles >= 3 cycles := 0;
            running := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
