MODULE CameraPick
    ! A PLC writes a camera's pick position to analog inputs; the code clamps it and
    ! retries below 80. Arithmetic on the value has no exact default: the check takes the
    ! numbers x and z are compared with (80, 110; 350), neighbours, 0, and names them.
    VAR signalai aiX;
    VAR signalai aiZ;
    VAR pos posCam := [0, 0, 0];
    VAR num tries := 0;

    PROC main()
        AliasIO "AI_X", aiX;
        AliasIO "AI_Z", aiZ;
        posCam.x := AInput(aiX) * 1;
        posCam.z := AInput(aiZ) + 0;
        WHILE posCam.x < 80 AND tries < 2 DO
            tries := tries + 1;
            posCam.x := AInput(aiX) * 1;
        ENDWHILE
        IF posCam.z > 350 posCam.z := 350;
        IF posCam.x < 110 posCam.x := 130;
    ENDPROC
ENDMODULE
