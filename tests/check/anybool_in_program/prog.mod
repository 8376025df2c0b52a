MODULE AnyBoolInProgram
    ! AnyBool is for environment models only.
    VAR bool coin := FALSE;

    PROC main()
        coin := AnyBool();
    ENDPROC
ENDMODULE
