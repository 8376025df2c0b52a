MODULE TasksStopCounter
    PERS num count;
    PROC main()
        WHILE TRUE DO
            count := count + 1;
            IF count > 2 count := 0;
        ENDWHILE
    ENDPROC
ENDMODULE
