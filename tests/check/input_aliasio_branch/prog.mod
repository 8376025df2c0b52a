MODULE InputAliasIOBranch
    ! A declared signaldi bound with AliasIO to the free input DI_SENSOR.
    VAR signaldi sensor;
    VAR bool seen := FALSE;

    PROC main()
        AliasIO "DI_SENSOR", sensor;
        WHILE TRUE DO
            IF sensor = 1 THEN
                seen := TRUE;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
