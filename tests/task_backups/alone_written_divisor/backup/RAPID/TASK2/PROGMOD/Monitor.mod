MODULE Monitor
    ! Written for the test (issue 27): a ratio that needs nCode <> -1.
    PERS num nCode := 0;
    VAR num nRatio := 0;

    PROC main()
        WHILE TRUE DO
            nRatio := 100 / (nCode + 1);
            WaitTime 0.1;
        ENDWHILE
    ENDPROC
ENDMODULE
