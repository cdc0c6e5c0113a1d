<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>BoneEditCommand</name>
    <message>
        <source>Split Bone %1 of %2</source>
        <translation>Dividir hueso %1 de %2</translation>
    </message>
    <message>
        <source>Delete Bone %1 of %2</source>
        <translation>Eliminar hueso %1 de %2</translation>
    </message>
    <message>
        <source>%1 in %2 ms: %3 vertices and %4 re-skinned</source>
        <translation>%1 en %2 ms: %3 vértices y %4 revinculados</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 hueso</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 huesos</translation>
    </message>
    <message>
        <source>Connect Bone %1 of %2</source>
        <translation>Conectar el hueso %1 de %2</translation>
    </message>
</context>
<context>
    <name>ClipListCommand</name>
    <message>
        <source>New clip %1 of %2</source>
        <translation>Nuevo clip %1 de %2</translation>
    </message>
    <message>
        <source>Duplicate clip %1 of %2 as %3</source>
        <translation>Duplicar clip %1 de %2 como %3</translation>
    </message>
    <message>
        <source>Rename clip %1 of %2 to %3</source>
        <translation>Renombrar clip %1 de %2 a %3</translation>
    </message>
    <message>
        <source>Delete clip %1 of %2</source>
        <translation>Eliminar clip %1 de %2</translation>
    </message>
    <message>
        <source>Play clip %1 on %2</source>
        <translation>Reproducir clip %1 en %2</translation>
    </message>
</context>
<context>
    <name>CreatePartCommand</name>
    <message>
        <source>Part %1</source>
        <translation>Pieza %1</translation>
    </message>
    <message>
        <source>Create %1</source>
        <translation>Crear %1</translation>
    </message>
</context>
<context>
    <name>CutPartCommand</name>
    <message>
        <source>Cut %1</source>
        <translation>Cortar %1</translation>
    </message>
    <message>
        <source>%1 cut</source>
        <translation>%1 cortada</translation>
    </message>
</context>
<context>
    <name>DeleteKeyCommand</name>
    <message>
        <source>Delete key of %1 at %2 s</source>
        <translation>Eliminar clave de %1 en %2 s</translation>
    </message>
</context>
<context>
    <name>DeletePartCommand</name>
    <message>
        <source>Delete %1</source>
        <translation>Eliminar %1</translation>
    </message>
</context>
<context>
    <name>DraggedRigCarry</name>
    <message numerus="yes">
        <source>the rotations of %n joint(s)</source>
        <translation>
            <numerusform>la rotación de %n articulación</numerusform>
            <numerusform>las rotaciones de %n articulaciones</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pin(s)</source>
        <translation>
            <numerusform>%n fijación</numerusform>
            <numerusform>%n fijaciones</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n key(s)</source>
        <translation>
            <numerusform>%n clave</numerusform>
            <numerusform>%n claves</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the rotations of joint(s) %1 (in the merged skeleton they would turn other bones)</source>
        <translation>
            <numerusform>la rotación de la articulación %1 (en el esqueleto fusionado giraría otros huesos)</numerusform>
            <numerusform>las rotaciones de las articulaciones %1 (en el esqueleto fusionado girarían otros huesos)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the pin(s) of joint(s) %1 (pruned)</source>
        <translation>
            <numerusform>la fijación de la articulación %1 (eliminada)</numerusform>
            <numerusform>las fijaciones de las articulaciones %1 (eliminadas)</numerusform>
        </translation>
    </message>
    <message>
        <source>its root offset</source>
        <translation>su desplazamiento de raíz</translation>
    </message>
    <message>
        <source>from %1: </source>
        <translation>de %1: </translation>
    </message>
    <message>
        <source>kept %1</source>
        <translation>se conserva %1</translation>
    </message>
    <message>
        <source>dropped %1</source>
        <translation>se descarta %1</translation>
    </message>
    <message>
        <source>; its keys now play at the target&apos;s frame rate and interpolation</source>
        <translation>; sus claves se reproducen ahora con la velocidad de fotogramas y la interpolación del destino</translation>
    </message>
</context>
<context>
    <name>EngineMessage</name>
    <message>
        <source>Point %1 of the stroke (counting from 0) is %2, which is not a finite number: the sketch data is corrupt. Redraw the stroke.</source>
        <translation>El punto %1 del trazo (contando desde 0) es %2, que no es un número finito: los datos del boceto están dañados. Vuelva a dibujar el trazo.</translation>
    </message>
    <message>
        <source>The stroke has only 1 distinct point; a silhouette needs at least 3 points that enclose an area. Draw a closed outline.</source>
        <translation>El trazo tiene un solo punto distinto; una silueta necesita al menos 3 puntos que encierren un área. Dibuje un contorno cerrado.</translation>
    </message>
    <message>
        <source>The stroke has only %1 distinct points; a silhouette needs at least 3 points that enclose an area. Draw a closed outline.</source>
        <translation>El trazo tiene solo %1 puntos distintos; una silueta necesita al menos 3 puntos que encierren un área. Dibuje un contorno cerrado.</translation>
    </message>
    <message>
        <source>The stroke has %1 points but only %2 distinct positions; the other %3 repeat them, which is too little to describe a silhouette. Draw the outline as one continuous stroke.</source>
        <translation>El trazo tiene %1 puntos pero solo %2 posiciones distintas; los otros %3 las repiten, demasiado poco para describir una silueta. Dibuje el contorno en un solo trazo continuo.</translation>
    </message>
    <message>
        <source>The stroke is too long for its size: at the requested spacing its outline would need more than %1 points. Draw a simpler outline or use a larger spacing.</source>
        <translation>El trazo es demasiado largo para su tamaño: con la separación pedida su contorno necesitaría más de %1 puntos. Dibuje un contorno más sencillo o use una separación mayor.</translation>
    </message>
    <message>
        <source>All points of the stroke lie on (nearly) one straight line, so it encloses no area. Draw a closed silhouette.</source>
        <translation>Todos los puntos del trazo están (casi) en una línea recta, así que no encierra ningún área. Dibuje una silueta cerrada.</translation>
    </message>
    <message>
        <source>The stroke crosses itself near %1: draw a silhouette that does not cross itself.</source>
        <translation>El trazo se cruza a sí mismo cerca de %1: dibuje una silueta que no se cruce.</translation>
    </message>
    <message>
        <source>The stroke encloses almost no area (it runs back along itself). Draw a silhouette with some width.</source>
        <translation>El trazo casi no encierra área (vuelve sobre sí mismo). Dibuje una silueta con algo de anchura.</translation>
    </message>
    <message>
        <source>The stroke&apos;s coordinates are too large to process; scale the sketch down.</source>
        <translation>Las coordenadas del trazo son demasiado grandes para procesarlas; reduzca la escala del boceto.</translation>
    </message>
    <message>
        <source>the outline touches itself at (%1, %2)</source>
        <translation>el contorno se toca a sí mismo en (%1, %2)</translation>
    </message>
    <message>
        <source>the outline crosses itself: draw a silhouette that does not cross itself</source>
        <translation>el contorno se cruza a sí mismo: dibuje una silueta que no se cruce</translation>
    </message>
    <message>
        <source>an outline needs at least three points</source>
        <translation>un contorno necesita al menos tres puntos</translation>
    </message>
    <message>
        <source>the outline has repeated points</source>
        <translation>el contorno tiene puntos repetidos</translation>
    </message>
    <message>
        <source>the outline encloses no area</source>
        <translation>el contorno no encierra ningún área</translation>
    </message>
    <message>
        <source>the outline is too simple to have an axis: draw a larger, rounder shape</source>
        <translation>el contorno es demasiado simple para tener un eje: dibuje una forma más grande y redondeada</translation>
    </message>
    <message>
        <source>the sketch is %1 across; sizes from %2 to %3 are supported</source>
        <translation>el boceto mide %1 de ancho; se admiten tamaños de %2 a %3</translation>
    </message>
    <message>
        <source>the sketch lies too far from the origin for its size: near %1 doubles are %2 apart, more than a millionth of its edges (%3); move it within %4 of the origin</source>
        <translation>el boceto está muy lejos del origen para su tamaño: cerca de %1 los números flotantes distan %2, más de una millonésima de sus aristas (%3); acérquelo a menos de %4 del origen</translation>
    </message>
    <message>
        <source>the edge length %1 is too small for this sketch: it would give about %2 vertices, more than the %3 allowed; use 0 (automatic: %4) or an edge length of at least %5</source>
        <translation>la longitud de arista %1 es demasiado pequeña para este boceto: daría unos %2 vértices, más de los %3 permitidos; use 0 (automática: %4) o al menos %5</translation>
    </message>
    <message>
        <source>the surface has a vertex with a non-finite coordinate; the sketch&apos;s numbers are beyond what double precision can build</source>
        <translation>la superficie tiene un vértice con una coordenada no finita; los números del boceto superan lo que la doble precisión puede construir</translation>
    </message>
    <message>
        <source>the surface has %1 degenerate faces; double precision cannot build this sketch at its position and size</source>
        <translation>la superficie tiene %1 caras degeneradas; la doble precisión no puede construir este boceto en su posición y tamaño</translation>
    </message>
    <message>
        <source>the target edge length must be 0 (automatic) or a positive length</source>
        <translation>la longitud de arista objetivo debe ser 0 (automática) o una longitud positiva</translation>
    </message>
    <message>
        <source>least-squares smoothing failed: the surface system could not be factored</source>
        <translation>falló el suavizado por mínimos cuadrados: no se pudo factorizar el sistema de la superficie</translation>
    </message>
    <message>
        <source>least-squares smoothing failed: the surface system has no finite solution</source>
        <translation>falló el suavizado por mínimos cuadrados: el sistema de la superficie no tiene solución finita</translation>
    </message>
    <message>
        <source>Only rigged parts can be merged; rig the imported mesh first.</source>
        <translation>Solo se pueden fusionar piezas con rig; ponga primero un rig a la malla importada.</translation>
    </message>
    <message>
        <source>The merge gave an invalid part (%1); nothing was changed.</source>
        <translation>La fusión dio una pieza no válida (%1); no se ha cambiado nada.</translation>
    </message>
    <message>
        <source>The dragged part has no joint %1.</source>
        <translation>La pieza arrastrada no tiene la articulación %1.</translation>
    </message>
    <message>
        <source>The target part has no joint %1.</source>
        <translation>La pieza de destino no tiene la articulación %1.</translation>
    </message>
    <message>
        <source>The target part has no bone %1.</source>
        <translation>La pieza de destino no tiene el hueso %1.</translation>
    </message>
    <message>
        <source>The two joints to connect are at the same place; snap them instead.</source>
        <translation>Las dos articulaciones que se van a conectar están en el mismo sitio; únalas en su lugar.</translation>
    </message>
    <message>
        <source>One of the surfaces intersects itself, so the parts cannot be merged. Rebuild it with a larger edge length or smoothing, then merge again.</source>
        <translation>Una de las superficies se interseca a sí misma, así que las piezas no se pueden fusionar. Reconstrúyala con una longitud de arista mayor o con suavizado y vuelva a fusionar.</translation>
    </message>
    <message>
        <source>The merged surface would not be a manifold (the parts touch at a point or along a line). Move the dragged part so that it overlaps the other one, then merge again.</source>
        <translation>La superficie fusionada no sería una variedad (las piezas se tocan en un punto o a lo largo de una línea). Mueva la pieza arrastrada para que se solape con la otra y vuelva a fusionar.</translation>
    </message>
    <message>
        <source>The parts do not touch. Drag one part so that it overlaps the other, then merge.</source>
        <translation>Las piezas no se tocan. Arrastre una pieza para que se solape con la otra y luego fusione.</translation>
    </message>
    <message>
        <source>One part lies entirely inside the other, so merging would only delete it. Drag it so that it sticks out of the other part, then merge.</source>
        <translation>Una pieza está totalmente dentro de la otra, así que fusionarlas solo la borraría. Arrástrela para que sobresalga de la otra pieza y luego fusione.</translation>
    </message>
    <message>
        <source>The local skin weights could not be solved; use the global re-computation.</source>
        <translation>No se pudieron resolver los pesos de piel locales; use el recálculo global.</translation>
    </message>
    <message>
        <source>Only rigged parts can be cut; rig the imported mesh first.</source>
        <translation>Solo se pueden cortar piezas con rig; ponga primero un rig a la malla importada.</translation>
    </message>
    <message>
        <source>The cut needs a plane: a finite point and a non-zero normal.</source>
        <translation>El corte necesita un plano: un punto finito y una normal no nula.</translation>
    </message>
    <message>
        <source>The cut&apos;s stroke has a point that is not a finite number.</source>
        <translation>El trazo del corte tiene un punto que no es un número finito.</translation>
    </message>
    <message>
        <source>The cut does not cross the part. Draw it across the part, from one side of its outline to the other.</source>
        <translation>El corte no atraviesa la pieza. Trácelo a través de la pieza, de un lado de su contorno al otro.</translation>
    </message>
    <message>
        <source>The cut crosses the part more than once (it would make %1 pieces). Cut where it crosses only once, or cut again.</source>
        <translation>El corte atraviesa la pieza más de una vez (saldrían %1 trozos). Corte donde la atraviese una sola vez, o vuelva a cortar.</translation>
    </message>
    <message>
        <source>The cut leaves two pieces on the same side of its plane; cut elsewhere.</source>
        <translation>El corte deja dos trozos al mismo lado de su plano; corte en otro sitio.</translation>
    </message>
    <message>
        <source>The cut leaves a piece without a bone. Cut across a bone, nearer the middle of the part.</source>
        <translation>El corte deja un trozo sin hueso. Corte a través de un hueso, más cerca del centro de la pieza.</translation>
    </message>
    <message>
        <source>The cut leaves a piece whose skeleton is not one tree; cut elsewhere.</source>
        <translation>El corte deja un trozo cuyo esqueleto no es un solo árbol; corte en otro sitio.</translation>
    </message>
    <message>
        <source>The patch&apos;s skin weights could not be solved; cut elsewhere.</source>
        <translation>No se pudieron resolver los pesos de piel del parche; corte en otro sitio.</translation>
    </message>
    <message>
        <source>The cut gave an invalid piece (%1); nothing was changed.</source>
        <translation>El corte dio un trozo no válido (%1); no se ha cambiado nada.</translation>
    </message>
    <message>
        <source>A cut needs a stroke of two points or more and a view direction.</source>
        <translation>Un corte necesita un trazo de dos o más puntos y una dirección de vista.</translation>
    </message>
    <message>
        <source>The cut&apos;s stroke must not start and end at the same point.</source>
        <translation>El trazo del corte no debe empezar y terminar en el mismo punto.</translation>
    </message>
    <message>
        <source>The bone edit gave an invalid part (%1); nothing was changed.</source>
        <translation>La edición del hueso dio una pieza no válida (%1); no se ha cambiado nada.</translation>
    </message>
    <message>
        <source>The part has no skeleton.</source>
        <translation>La pieza no tiene esqueleto.</translation>
    </message>
    <message>
        <source>The part has no bone %1.</source>
        <translation>La pieza no tiene el hueso %1.</translation>
    </message>
    <message>
        <source>That is too close to a joint to split the bone; pick a point nearer its middle.</source>
        <translation>Eso está demasiado cerca de una articulación para dividir el hueso; elija un punto más cerca de su centro.</translation>
    </message>
    <message>
        <source>No part of the surface is led by that bone where it would be split.</source>
        <translation>Ninguna zona de la superficie depende de ese hueso donde se dividiría.</translation>
    </message>
    <message>
        <source>A part keeps at least one bone; this is its only one.</source>
        <translation>Una pieza conserva al menos un hueso; este es el único que tiene.</translation>
    </message>
    <message>
        <source>The IK target is not a finite point.</source>
        <translation>El objetivo de IK no es un punto finito.</translation>
    </message>
    <message>
        <source>Cannot pose a skeleton without joints.</source>
        <translation>No se puede posar un esqueleto sin articulaciones.</translation>
    </message>
    <message>
        <source>Cannot pose a skeleton without a valid root joint.</source>
        <translation>No se puede posar un esqueleto sin una articulación raíz válida.</translation>
    </message>
    <message>
        <source>The skeleton has no joint %1.</source>
        <translation>El esqueleto no tiene la articulación %1.</translation>
    </message>
    <message>
        <source>The pose gives joint %1 a rotation that is not a finite, non-zero quaternion.</source>
        <translation>La pose da a la articulación %1 una rotación que no es un cuaternión finito y no nulo.</translation>
    </message>
    <message>
        <source>The pose&apos;s root translation is not finite.</source>
        <translation>La traslación de la raíz de la pose no es finita.</translation>
    </message>
    <message>
        <source>There is already a key at exactly %1 s.</source>
        <translation>Ya hay una clave exactamente en %1 s.</translation>
    </message>
    <message>
        <source>There is no key at exactly %1 s.</source>
        <translation>No hay ninguna clave exactamente en %1 s.</translation>
    </message>
    <message>
        <source>There is no key at %1 s.</source>
        <translation>No hay ninguna clave en %1 s.</translation>
    </message>
    <message>
        <source>There is no key at %1 s to move.</source>
        <translation>No hay ninguna clave en %1 s que mover.</translation>
    </message>
    <message>
        <source>There is no key at %1 s to delete.</source>
        <translation>No hay ninguna clave en %1 s que eliminar.</translation>
    </message>
    <message>
        <source>The clip has no keys.</source>
        <translation>El clip no tiene claves.</translation>
    </message>
    <message>
        <source>Cannot play a clip without keys.</source>
        <translation>No se puede reproducir un clip sin claves.</translation>
    </message>
    <message>
        <source>A key&apos;s pose must have finite, non-zero rotations and a finite translation.</source>
        <translation>La pose de una clave debe tener rotaciones finitas no nulas y una traslación finita.</translation>
    </message>
    <message>
        <source>The part has no bone %1 to paint.</source>
        <translation>La pieza no tiene el hueso %1 para pintar.</translation>
    </message>
    <message>
        <source>Bone %1 is locked; unlock it to paint it.</source>
        <translation>El hueso %1 está bloqueado; desbloquéelo para pintarlo.</translation>
    </message>
    <message>
        <source>A brush needs a finite centre, a positive radius, and a strength and value between 0 and 1.</source>
        <translation>Un pincel necesita un centro finito, un radio positivo y una fuerza y un valor entre 0 y 1.</translation>
    </message>
    <message>
        <source>Front faces only needs a finite, non-zero view direction.</source>
        <translation>«Solo caras frontales» necesita una dirección de vista finita y no nula.</translation>
    </message>
    <message>
        <source>The clean threshold must be at least 0 and below 1.</source>
        <translation>El umbral de limpieza debe ser al menos 0 y menor que 1.</translation>
    </message>
    <message>
        <source>A vertex needs at least one influence.</source>
        <translation>Un vértice necesita al menos una influencia.</translation>
    </message>
    <message>
        <source>Smooth All needs a factor from 0 to 1 and 1 to 100 passes.</source>
        <translation>«Suavizar todo» necesita un factor de 0 a 1 y de 1 a 100 pasadas.</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: the folder %2 does not exist</source>
        <translation>no se puede escribir %1: la carpeta %2 no existe</translation>
    </message>
    <message>
        <source>cannot write %1: it is a folder</source>
        <translation>no se puede escribir %1: es una carpeta</translation>
    </message>
    <message>
        <source>cannot write %1: the file is read-only</source>
        <translation>no se puede escribir %1: el archivo es de solo lectura</translation>
    </message>
    <message>
        <source>cannot write %1: cannot create a file in %2: %3</source>
        <translation>no se puede escribir %1: no se puede crear un archivo en %2: %3</translation>
    </message>
    <message>
        <source>cannot write %1: %2 (is the disk full?)</source>
        <translation>no se puede escribir %1: %2 (¿está lleno el disco?)</translation>
    </message>
    <message>
        <source>cannot write %1: cannot keep its permissions: %2</source>
        <translation>no se puede escribir %1: no se pueden conservar sus permisos: %2</translation>
    </message>
    <message>
        <source>cannot export: there is no part</source>
        <translation>no se puede exportar: no hay ninguna pieza</translation>
    </message>
    <message>
        <source>cannot export part &apos;%1&apos;: it has no surface</source>
        <translation>no se puede exportar la pieza «%1»: no tiene superficie</translation>
    </message>
    <message>
        <source>cannot export part &apos;%1&apos;: its skin weights do not match its surface</source>
        <translation>no se puede exportar la pieza «%1»: sus pesos de piel no corresponden a su superficie</translation>
    </message>
    <message>
        <source>cannot export the clip: the times %1 s and %2 s are too close for 32-bit precision this far from 0 s; move the keys nearer to 0 s or further apart</source>
        <translation>no se puede exportar el clip: los tiempos %1 s y %2 s están demasiado juntos para la precisión de 32 bits tan lejos de 0 s; acerque las claves a 0 s o sepárelas más</translation>
    </message>
    <message>
        <source>subdivision levels must be from 0 to 4, not %1</source>
        <translation>los niveles de subdivisión deben ir de 0 a 4, no %1</translation>
    </message>
    <message>
        <source>subdividing &apos;%1&apos; %2 times would give over %3 vertices; use fewer levels</source>
        <translation>subdividir «%1» %2 veces daría más de %3 vértices; use menos niveles</translation>
    </message>
    <message>
        <source>decimating needs a target of at least 4 faces, not %1</source>
        <translation>diezmar necesita un objetivo de al menos 4 caras, no %1</translation>
    </message>
    <message>
        <source>the surface is not manifold, so it cannot be decimated</source>
        <translation>la superficie no es una variedad, así que no se puede diezmar</translation>
    </message>
    <message>
        <source>%1 already has a skeleton. Rig parts without one (imported meshes); to start a sketched part&apos;s rig again, use Recompute Weights or Rebuild.</source>
        <translation>%1 ya tiene un esqueleto. Riggea piezas sin esqueleto (mallas importadas); para rehacer el rig de una pieza dibujada, usa Recalcular pesos o Reconstruir.</translation>
    </message>
    <message>
        <source>%1 has no surface to rig.</source>
        <translation>%1 no tiene superficie que riggear.</translation>
    </message>
    <message>
        <source>The mesh has only %1 usable faces; a rig needs a closed surface that bounds a volume.</source>
        <translation>La malla solo tiene %1 caras utilizables; un rig necesita una superficie cerrada que encierre un volumen.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: %1</source>
        <translation>No se encontró ningún esqueleto en la malla: %1</translation>
    </message>
    <message>
        <source>Rigging was cancelled.</source>
        <translation>Se canceló el rigging.</translation>
    </message>
    <message>
        <source>joined %1 vertices that sat at the same position (split seams)</source>
        <translation>se unieron %1 vértices que estaban en la misma posición (costuras separadas)</translation>
    </message>
    <message>
        <source>removed %1 degenerate faces (no area)</source>
        <translation>se eliminaron %1 caras degeneradas (sin área)</translation>
    </message>
    <message>
        <source>removed %1 duplicate faces</source>
        <translation>se eliminaron %1 caras duplicadas</translation>
    </message>
    <message>
        <source>removed %1 vertices no face uses</source>
        <translation>se eliminaron %1 vértices que ninguna cara usa</translation>
    </message>
    <message>
        <source>split %1 vertices where separate sheets touched</source>
        <translation>se separaron %1 vértices donde se tocaban láminas distintas</translation>
    </message>
    <message>
        <source>turned the faces outward (they faced inward)</source>
        <translation>se giraron las caras hacia fuera (miraban hacia dentro)</translation>
    </message>
    <message>
        <source>filled %1 small holes with %2 new vertices</source>
        <translation>se rellenaron %1 agujeros pequeños con %2 vértices nuevos</translation>
    </message>
    <message>
        <source>the mesh is open (%1 borders, the longest of %2 edges)</source>
        <translation>la malla está abierta (%1 bordes, el más largo de %2 aristas)</translation>
    </message>
    <message>
        <source>the mesh is %1 separate pieces</source>
        <translation>la malla está formada por %1 trozos separados</translation>
    </message>
    <message>
        <source>%1 pairs of the mesh&apos;s faces cross each other</source>
        <translation>%1 pares de caras de la malla se cruzan</translation>
    </message>
    <message>
        <source>the mesh is not a manifold (more than two faces meet at an edge)</source>
        <translation>la malla no es una variedad (más de dos caras se encuentran en una arista)</translation>
    </message>
    <message>
        <source>A vertex of the mesh is not a finite number: the file is corrupt.</source>
        <translation>Un vértice de la malla no es un número finito: el archivo está dañado.</translation>
    </message>
    <message>
        <source>A face of the mesh names vertex %1, but the mesh has only %2 vertices: the file is corrupt.</source>
        <translation>Una cara de la malla nombra el vértice %1, pero la malla solo tiene %2 vértices: el archivo está dañado.</translation>
    </message>
    <message>
        <source>The mesh has %1 faces: rigging it would need more than the %2 MiB of memory allowed. Decimate it in your modelling tool (in Blender: the Decimate modifier) and import it again.</source>
        <translation>La malla tiene %1 caras: riggearla necesitaría más de los %2 MiB de memoria permitidos. Diezmala en tu programa de modelado (en Blender: el modificador Decimate) e impórtala de nuevo.</translation>
    </message>
    <message>
        <source>the skeleton and weights were computed on a closed proxy of %1 vertices wrapped around the mesh&apos;s %2 pieces; the mesh itself is kept as it was</source>
        <translation>el esqueleto y los pesos se calcularon sobre una envoltura cerrada de %1 vértices alrededor de los %2 trozos de la malla; la malla misma queda como estaba</translation>
    </message>
    <message>
        <source>%1 small pieces (eyes, teeth, buttons) follow bone %2</source>
        <translation>%1 trozos pequeños (ojos, dientes, botones) siguen al hueso %2</translation>
    </message>
    <message>
        <source>%1 more small pieces follow one bone each</source>
        <translation>%1 trozos pequeños más siguen a un hueso cada uno</translation>
    </message>
    <message>
        <source>the mesh has %1 vertices, too many to compute the skeleton on directly</source>
        <translation>la malla tiene %1 vértices, demasiados para calcular el esqueleto directamente sobre ella</translation>
    </message>
    <message>
        <source>the mesh&apos;s edges are long for its size (on average %1% of its diagonal), too coarse to compute the skeleton on directly</source>
        <translation>las aristas de la malla son largas para su tamaño (de media el %1% de su diagonal), demasiado gruesa para calcular el esqueleto directamente sobre ella</translation>
    </message>
    <message>
        <source>%1 pieces of the proxy lie apart from the body and follow its nearest bones</source>
        <translation>%1 trozos de la envoltura quedan apartados del cuerpo y siguen sus huesos más cercanos</translation>
    </message>
    <message>
        <source>Bone %1 is not connected to its parent; connect it first (Edit &gt; Connect Bone).</source>
        <translation>El hueso %1 no está conectado a su padre; conéctelo primero (Editar &gt; Conectar hueso).</translation>
    </message>
    <message>
        <source>Bone %1 is already connected to its parent.</source>
        <translation>El hueso %1 ya está conectado a su padre.</translation>
    </message>
    <message>
        <source>Bone %1 starts at the skeleton&apos;s root: it has no parent to connect to.</source>
        <translation>El hueso %1 empieza en la raíz del esqueleto: no tiene padre al que conectarse.</translation>
    </message>
    <message>
        <source>The surface would intersect itself (%1 crossing face pairs) near (%2, %3): the outline is too thin or turns too sharply there. Widen it there or use a smaller edge length.</source>
        <translation>La superficie se intersecaría a sí misma (%1 pares de caras cruzadas) en (%2, %3): el contorno es demasiado fino o gira muy bruscamente ahí. Ensánchelo o use aristas más cortas.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be rebuilt: it was not drawn as one sketch (it comes from a merge, a cut, a bone edit or an import), so there is no stroke to build it from.</source>
        <translation>«%1» no se puede reconstruir: no se dibujó como un solo boceto (procede de una fusión, un corte, una edición de huesos o una importación), así que no hay trazo desde el que construirla.</translation>
    </message>
    <message>
        <source>The target part cannot be merged: %1 Merging needs closed, consistently oriented surfaces.</source>
        <translation>La pieza de destino no se puede fusionar: %1 La fusión necesita superficies cerradas y orientadas de forma coherente.</translation>
    </message>
    <message>
        <source>The dragged part cannot be merged: %1 Merging needs closed, consistently oriented surfaces.</source>
        <translation>La pieza arrastrada no se puede fusionar: %1 La fusión necesita superficies cerradas y orientadas de forma coherente.</translation>
    </message>
    <message>
        <source>The target part&apos;s surface intersects itself (%1 crossing face pairs), so the parts cannot be merged. Rebuild it with a larger edge length or smoothing first.</source>
        <translation>La superficie de la pieza de destino se interseca a sí misma (%1 pares de caras cruzadas), así que las piezas no se pueden fusionar. Reconstrúyala antes con aristas más largas o suavizado.</translation>
    </message>
    <message>
        <source>The dragged part&apos;s surface intersects itself (%1 crossing face pairs), so the parts cannot be merged. Rebuild it with a larger edge length or smoothing first.</source>
        <translation>La superficie de la pieza arrastrada se interseca a sí misma (%1 pares de caras cruzadas), así que las piezas no se pueden fusionar. Reconstrúyala antes con aristas más largas o suavizado.</translation>
    </message>
    <message>
        <source>The joints to connect are %1 apart, less than the shortest bone allowed (%2); snap them instead.</source>
        <translation>Las articulaciones que se van a conectar están a %1 de distancia, menos que el hueso más corto permitido (%2); únalas en su lugar.</translation>
    </message>
    <message>
        <source>The part cannot be cut: %1 Cutting needs a closed, consistently oriented surface.</source>
        <translation>La pieza no se puede cortar: %1 El corte necesita una superficie cerrada y orientada de forma coherente.</translation>
    </message>
    <message>
        <source>The cut would leave a piece without a bone: its only one would be %1 long, shorter than the shortest bone allowed (%2). Cut farther from the joint.</source>
        <translation>El corte dejaría un trozo sin hueso: el único mediría %1, menos que el hueso más corto permitido (%2). Corte más lejos de la articulación.</translation>
    </message>
    <message>
        <source>Splitting there would leave a bone %1 long, shorter than the shortest bone allowed (%2); split nearer the bone&apos;s middle.</source>
        <translation>Dividir ahí dejaría un hueso de %1, menos que el hueso más corto permitido (%2); divida más cerca del centro del hueso.</translation>
    </message>
    <message>
        <source>Deleting the bone would leave bone %1 only %2 long, shorter than the shortest bone allowed (%3); delete a neighbouring bone instead.</source>
        <translation>Eliminar el hueso dejaría el hueso %1 con solo %2 de longitud, menos que el hueso más corto permitido (%3); elimine en su lugar un hueso vecino.</translation>
    </message>
    <message>
        <source>A key time must be a finite number of seconds.</source>
        <translation>El tiempo de una clave debe ser un número finito de segundos.</translation>
    </message>
    <message>
        <source>A key at %1 s is out of range: keys lie at 0 s or later.</source>
        <translation>Una clave en %1 s está fuera de rango: las claves están en 0 s o después.</translation>
    </message>
    <message>
        <source>A key at %1 s is out of range: keys lie from 0 s to %2 s.</source>
        <translation>Una clave en %1 s está fuera de rango: las claves están entre 0 s y %2 s.</translation>
    </message>
    <message>
        <source>A clip&apos;s frame rate must be a positive number of frames per second.</source>
        <translation>La velocidad de fotogramas de un clip debe ser un número positivo de fotogramas por segundo.</translation>
    </message>
    <message>
        <source>The part has no bone %1 to lock.</source>
        <translation>La pieza no tiene el hueso %1 para bloquear.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: there is no such file.</source>
        <translation>No se puede importar «%1»: no existe ese archivo.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: it is not a file.</source>
        <translation>No se puede importar «%1»: no es un archivo.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the program that reads imports (rigmesh) is not installed.</source>
        <translation>No se puede importar «%1»: el programa que lee las importaciones (rigmesh) no está instalado.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the import reader could not be started (%2).</source>
        <translation>No se puede importar «%1»: no se pudo iniciar el lector de importaciones (%2).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: reading it took longer than %2 s, so it was stopped (the file is probably broken).</source>
        <translation>No se puede importar «%1»: leerlo tardó más de %2 s, así que se detuvo (probablemente el archivo está dañado).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the importer crashed on it (%2); the file is probably broken.</source>
        <translation>No se puede importar «%1»: el importador falló con él (%2); probablemente el archivo está dañado.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: reading it needed more than %2 of memory, so it was stopped.</source>
        <translation>No se puede importar «%1»: leerlo necesitaba más de %2 de memoria, así que se detuvo.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the importer failed (exit status %2).</source>
        <translation>No se puede importar «%1»: el importador falló (estado de salida %2).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the importer returned bad data (%2).</source>
        <translation>No se puede importar «%1»: el importador devolvió datos erróneos (%2).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: its part &quot;%2&quot; is not usable: %3</source>
        <translation>No se puede importar «%1»: su pieza «%2» no se puede usar: %3</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>No se puede importar «%1»: %2</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: it is damaged or not in a format the importer knows.</source>
        <translation>No se puede importar «%1»: está dañado o en un formato que el importador no conoce.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the file is incomplete.</source>
        <translation>No se puede importar «%1»: el archivo está incompleto.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: it holds no triangle mesh.</source>
        <translation>No se puede importar «%1»: no contiene ninguna malla de triángulos.</translation>
    </message>
    <message>
        <source>The mesh is too small for a bone: its only bone would be %1 long, shorter than the shortest bone allowed (%2).</source>
        <translation>La malla es demasiado pequeña para un hueso: su único hueso mediría %1, menos que el hueso más corto permitido (%2).</translation>
    </message>
    <message>
        <source>This part has no left-right mirror plane (its two sides differ by more than 2% of its size), so X-mirror cannot paint it.</source>
        <translation>Esta pieza no tiene plano de simetría izquierda-derecha (sus dos lados difieren en más del 2 % de su tamaño), así que el espejo en X no puede pintarla.</translation>
    </message>
    <message>
        <source>No part with id %1 in the document.</source>
        <translation>No hay ninguna pieza con el identificador %1 en el documento.</translation>
    </message>
    <message>
        <source>Part %1 has no joint %2.</source>
        <translation>La pieza %1 no tiene la articulación %2.</translation>
    </message>
    <message>
        <source>The pose of part %1 has a non-finite or zero rotation or translation.</source>
        <translation>La pose de la pieza %1 tiene una rotación o traslación no finita o nula.</translation>
    </message>
    <message>
        <source>The key at %1 s of part %2 has a non-finite or zero rotation or translation.</source>
        <translation>La clave en %1 s de la pieza %2 tiene una rotación o traslación no finita o nula.</translation>
    </message>
    <message>
        <source>The starting pose of part %1 has a non-finite or zero rotation or translation.</source>
        <translation>La pose inicial de la pieza %1 tiene una rotación o traslación no finita o nula.</translation>
    </message>
    <message>
        <source>The new pose of part %1 has a non-finite or zero rotation or translation.</source>
        <translation>La nueva pose de la pieza %1 tiene una rotación o traslación no finita o nula.</translation>
    </message>
    <message>
        <source>The starting pose names joint %1, which part %2 does not have.</source>
        <translation>La pose inicial nombra la articulación %1, que la pieza %2 no tiene.</translation>
    </message>
    <message>
        <source>The new pose names joint %1, which part %2 does not have.</source>
        <translation>La nueva pose nombra la articulación %1, que la pieza %2 no tiene.</translation>
    </message>
    <message>
        <source>The part has no skeleton to pose.</source>
        <translation>La pieza no tiene esqueleto que posar.</translation>
    </message>
    <message>
        <source>The part has no skeleton to edit.</source>
        <translation>La pieza no tiene esqueleto que editar.</translation>
    </message>
    <message>
        <source>The part has no surface to cut.</source>
        <translation>La pieza no tiene superficie que cortar.</translation>
    </message>
    <message>
        <source>The cut&apos;s view needs a direction and an up that is not along it.</source>
        <translation>La vista del corte necesita una dirección y un «arriba» que no vaya en esa dirección.</translation>
    </message>
    <message>
        <source>A part cannot be merged into itself.</source>
        <translation>Una pieza no se puede fusionar consigo misma.</translation>
    </message>
    <message>
        <source>%1 has no joint %2</source>
        <translation>%1 no tiene la articulación %2</translation>
    </message>
    <message>
        <source>The parts to merge are no longer in the document.</source>
        <translation>Las piezas que fusionar ya no están en el documento.</translation>
    </message>
    <message>
        <source>There is no such part.</source>
        <translation>No existe esa pieza.</translation>
    </message>
    <message>
        <source>The part is no longer in the document.</source>
        <translation>La pieza ya no está en el documento.</translation>
    </message>
    <message>
        <source>There is no part to rig.</source>
        <translation>No hay ninguna pieza a la que poner un rig.</translation>
    </message>
    <message>
        <source>The part changed while it was rigged; nothing was changed.</source>
        <translation>La pieza cambió mientras se le ponía el rig; no se ha cambiado nada.</translation>
    </message>
    <message>
        <source>The parts to rig together must be given in document order, once each.</source>
        <translation>Las piezas a las que poner un rig juntas deben darse en el orden del documento, una vez cada una.</translation>
    </message>
    <message>
        <source>There is no part to recompute the weights of.</source>
        <translation>No hay ninguna pieza cuyos pesos recalcular.</translation>
    </message>
    <message>
        <source>The part changed while its weights were recomputed; nothing was changed.</source>
        <translation>La pieza cambió mientras se recalculaban sus pesos; no se ha cambiado nada.</translation>
    </message>
    <message>
        <source>%1 holds no mesh to import</source>
        <translation>%1 no contiene ninguna malla que importar</translation>
    </message>
    <message>
        <source>there are no parts to export</source>
        <translation>no hay piezas que exportar</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not rigged yet: export it as OBJ, or hide it and export the visible parts</source>
        <translation>«%1» todavía no tiene rig: expórtela como OBJ, u ocúltela y exporte las piezas visibles</translation>
    </message>
    <message>
        <source>The history step &quot;%1&quot; cannot be written as a recipe step.</source>
        <translation>El paso del historial «%1» no se puede escribir como paso de receta.</translation>
    </message>
    <message>
        <source>lists and maps are nested more than %1 levels deep</source>
        <translation>las listas y los mapas están anidados a más de %1 niveles de profundidad</translation>
    </message>
    <message>
        <source>The frame rate must be between %1 and %2 frames per second.</source>
        <translation>La velocidad de fotogramas debe estar entre %1 y %2 fotogramas por segundo.</translation>
    </message>
    <message>
        <source>The frame range must lie within frames 0 to %1.</source>
        <translation>El rango de fotogramas debe estar entre los fotogramas 0 y %1.</translation>
    </message>
    <message>
        <source>The frame range must end after it starts.</source>
        <translation>El rango de fotogramas debe terminar después de empezar.</translation>
    </message>
    <message>
        <source>The frame range is longer than a clip can be.</source>
        <translation>El rango de fotogramas es más largo de lo que puede ser un clip.</translation>
    </message>
    <message>
        <source>Frame %1 is outside frames 0 to %2.</source>
        <translation>El fotograma %1 está fuera de los fotogramas 0 a %2.</translation>
    </message>
    <message>
        <source>A clip name must have 1 to %1 characters.</source>
        <translation>Un nombre de clip debe tener de 1 a %1 caracteres.</translation>
    </message>
    <message>
        <source>A clip name must not start or end with a space.</source>
        <translation>Un nombre de clip no debe empezar ni terminar con un espacio.</translation>
    </message>
    <message>
        <source>A clip name must not hold control characters.</source>
        <translation>Un nombre de clip no debe contener caracteres de control.</translation>
    </message>
    <message>
        <source>The part has two clips named &quot;%1&quot;.</source>
        <translation>La pieza tiene dos clips llamados «%1».</translation>
    </message>
    <message>
        <source>%1 already has a clip named &quot;%2&quot;.</source>
        <translation>%1 ya tiene un clip llamado «%2».</translation>
    </message>
    <message>
        <source>%1 has no clip named &quot;%2&quot;.</source>
        <translation>%1 no tiene ningún clip llamado «%2».</translation>
    </message>
    <message>
        <source>%1 has only this clip: a part keeps one clip (delete its keys instead).</source>
        <translation>%1 solo tiene este clip: una pieza conserva un clip (elimine sus claves en su lugar).</translation>
    </message>
    <message>
        <source>There are no keys to paste.</source>
        <translation>No hay claves que pegar.</translation>
    </message>
    <message>
        <source>There are no keys to move.</source>
        <translation>No hay claves que mover.</translation>
    </message>
    <message>
        <source>The keys&apos; offset is not a finite number of seconds.</source>
        <translation>El desplazamiento de las claves no es un número finito de segundos.</translation>
    </message>
    <message>
        <source>The part has no skeleton, so it has no weights to paint.</source>
        <translation>La pieza no tiene esqueleto, así que no tiene pesos que pintar.</translation>
    </message>
    <message>
        <source>The part has no skeleton, so it has no weights to lock.</source>
        <translation>La pieza no tiene esqueleto, así que no tiene pesos que bloquear.</translation>
    </message>
    <message>
        <source>The part has no skeleton, so it has no weights to clean up.</source>
        <translation>La pieza no tiene esqueleto, así que no tiene pesos que limpiar.</translation>
    </message>
    <message>
        <source>Only a part with a skeleton has weights to recompute.</source>
        <translation>Solo una pieza con esqueleto tiene pesos que recalcular.</translation>
    </message>
    <message>
        <source>Check Rig needs at least one influence and a positive tolerance.</source>
        <translation>Comprobar rig necesita al menos una influencia y una tolerancia positiva.</translation>
    </message>
    <message>
        <source>A skin weight refers to bone %1, which the skeleton does not have.</source>
        <translation>Un peso de piel se refiere al hueso %1, que el esqueleto no tiene.</translation>
    </message>
    <message>
        <source>Skin weights need at least one bone.</source>
        <translation>Los pesos de piel necesitan al menos un hueso.</translation>
    </message>
    <message>
        <source>Skin weights need at least one bone with finite end points.</source>
        <translation>Los pesos de piel necesitan al menos un hueso con extremos finitos.</translation>
    </message>
    <message>
        <source>The mesh has a vertex with a non-finite position.</source>
        <translation>La malla tiene un vértice con una posición no finita.</translation>
    </message>
    <message>
        <source>The mesh has a triangle that refers to a missing vertex.</source>
        <translation>La malla tiene un triángulo que se refiere a un vértice que no existe.</translation>
    </message>
    <message>
        <source>A bone cannot connect joint %1 to itself.</source>
        <translation>Un hueso no puede unir la articulación %1 consigo misma.</translation>
    </message>
    <message>
        <source>Only existing joints can be merged.</source>
        <translation>Solo se pueden fusionar articulaciones existentes.</translation>
    </message>
    <message>
        <source>The root joint %1 cannot hang from a bone.</source>
        <translation>La articulación raíz %1 no puede colgar de un hueso.</translation>
    </message>
    <message>
        <source>The skeleton has no bone %1.</source>
        <translation>El esqueleto no tiene el hueso %1.</translation>
    </message>
    <message>
        <source>Cannot choose a root for a skeleton without joints.</source>
        <translation>No se puede elegir una raíz para un esqueleto sin articulaciones.</translation>
    </message>
    <message>
        <source>the skeleton of this shape is invalid: %1</source>
        <translation>el esqueleto de esta forma no es válido: %1</translation>
    </message>
    <message>
        <source>subdividing &apos;%1&apos; failed: %2</source>
        <translation>no se pudo subdividir «%1»: %2</translation>
    </message>
    <message>
        <source>decimating &apos;%1&apos; failed: %2</source>
        <translation>no se pudo diezmar «%1»: %2</translation>
    </message>
    <message>
        <source>the pose demo needs a part with bones</source>
        <translation>la demostración de poses necesita una pieza con huesos</translation>
    </message>
    <message>
        <source>the outline has no elongated part to inflate: draw a longer shape</source>
        <translation>el contorno no tiene ninguna parte alargada que inflar: dibuje una forma más larga</translation>
    </message>
    <message>
        <source>a patch boundary needs at least three points</source>
        <translation>el borde de un parche necesita al menos tres puntos</translation>
    </message>
    <message>
        <source>the target edge length must be positive</source>
        <translation>la longitud de arista objetivo debe ser positiva</translation>
    </message>
    <message>
        <source>the edge length is too small for this patch: %1 lattice rows or columns</source>
        <translation>la longitud de arista es demasiado pequeña para este parche: %1 filas o columnas de retícula</translation>
    </message>
    <message>
        <source>the edge length is too small for this patch: %1 lattice points</source>
        <translation>la longitud de arista es demasiado pequeña para este parche: %1 puntos de retícula</translation>
    </message>
    <message>
        <source>least-squares smoothing needs at least one anchored vertex</source>
        <translation>el suavizado por mínimos cuadrados necesita al menos un vértice anclado</translation>
    </message>
    <message>
        <source>The target edge length must be 0 (automatic) or a positive length.</source>
        <translation>La longitud de arista objetivo debe ser 0 (automática) o una longitud positiva.</translation>
    </message>
    <message>
        <source>Cannot open &apos;%1&apos;: the file does not exist or is not readable.</source>
        <translation>No se puede abrir «%1»: el archivo no existe o no se puede leer.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: reading the file failed.</source>
        <translation>No se puede leer «%1»: la lectura del archivo falló.</translation>
    </message>
    <message>
        <source>Unsupported mesh file type &apos;%1&apos;: use .obj, .off or .ply.</source>
        <translation>Tipo de archivo de malla no admitido «%1»: use .obj, .off o .ply.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: a vertex needs three coordinates.</source>
        <translation>No se puede leer «%1»: línea %2: un vértice necesita tres coordenadas.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: a face needs at least three vertices.</source>
        <translation>No se puede leer «%1»: línea %2: una cara necesita al menos tres vértices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: face refers to vertex %3 but only %4 vertices are defined before it.</source>
        <translation>No se puede leer «%1»: línea %2: la cara se refiere al vértice %3, pero antes solo hay %4 vértices definidos.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: &apos;%3&apos; is not a finite number.</source>
        <translation>No se puede leer «%1»: línea %2: «%3» no es un número finito.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: &apos;%3&apos; is not an integer.</source>
        <translation>No se puede leer «%1»: línea %2: «%3» no es un número entero.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: invalid count &apos;%3&apos;.</source>
        <translation>No se puede leer «%1»: línea %2: cantidad no válida «%3».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting the OFF header.</source>
        <translation>No se puede leer «%1»: el archivo termina antes de tiempo, cuando se esperaba la cabecera OFF.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting the vertex and face counts.</source>
        <translation>No se puede leer «%1»: el archivo termina antes de tiempo, cuando se esperaba el número de vértices y caras.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting vertex %2 of %3.</source>
        <translation>No se puede leer «%1»: el archivo termina antes de tiempo, cuando se esperaba el vértice %2 de %3.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting face %2 of %3.</source>
        <translation>No se puede leer «%1»: el archivo termina antes de tiempo, cuando se esperaba la cara %2 de %3.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file does not start with &apos;OFF&apos;.</source>
        <translation>No se puede leer «%1»: el archivo no empieza por «OFF».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: expected the vertex and face counts.</source>
        <translation>No se puede leer «%1»: línea %2: se esperaba el número de vértices y caras.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: a face needs a corner count of at least 3 and that many vertex indices.</source>
        <translation>No se puede leer «%1»: línea %2: una cara necesita un número de esquinas de al menos 3 y ese número de índices de vértice.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: face refers to vertex %3 but there are %4 vertices.</source>
        <translation>No se puede leer «%1»: línea %2: la cara se refiere al vértice %3, pero hay %4 vértices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file does not start with &apos;ply&apos;.</source>
        <translation>No se puede leer «%1»: el archivo no empieza por «ply».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the header has no &apos;end_header&apos; line.</source>
        <translation>No se puede leer «%1»: la cabecera no tiene la línea «end_header».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the header has no &apos;format&apos; line.</source>
        <translation>No se puede leer «%1»: la cabecera no tiene la línea «format».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: unknown property type &apos;%3&apos;.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: tipo de propiedad desconocido «%3».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: unknown format &apos;%3&apos;.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: formato desconocido «%3».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: &apos;%3&apos; is not an integer.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: «%3» no es un número entero.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: invalid element count &apos;%3&apos;.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: número de elementos no válido «%3».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: a list count must have an integer type.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: la longitud de una lista debe tener un tipo entero.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: malformed property line.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: línea de propiedad mal formada.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: unexpected &apos;%3&apos;.</source>
        <translation>No se puede leer «%1»: línea %2 de la cabecera: «%3» inesperado.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file is truncated: it ends in %2 %3 of %4.</source>
        <translation>No se puede leer «%1»: el archivo está truncado: termina en %2 %3 de %4.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: &apos;%5&apos; is not a finite number.</source>
        <translation>No se puede leer «%1»: %2 %3 de %4: «%5» no es un número finito.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: list length is %5, outside [0, %6).</source>
        <translation>No se puede leer «%1»: %2 %3 de %4: la longitud de la lista es %5, fuera de [0, %6).</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: vertex index is %5, outside [0, %6).</source>
        <translation>No se puede leer «%1»: %2 %3 de %4: el índice de vértice es %5, fuera de [0, %6).</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: a face needs at least three vertices.</source>
        <translation>No se puede leer «%1»: %2 %3 de %4: una cara necesita al menos tres vértices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: a coordinate is not finite.</source>
        <translation>No se puede leer «%1»: %2 %3 de %4: una coordenada no es finita.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the vertex element lacks an x, y or z property.</source>
        <translation>No se puede leer «%1»: al elemento de vértices le falta una propiedad x, y o z.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file has more than one vertex element.</source>
        <translation>No se puede leer «%1»: el archivo tiene más de un elemento de vértices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the face element lacks a &apos;vertex_indices&apos; list.</source>
        <translation>No se puede leer «%1»: al elemento de caras le falta una lista «vertex_indices».</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file is truncated: element &apos;%2&apos; declares %3 entries that do not fit.</source>
        <translation>No se puede leer «%1»: el archivo está truncado: el elemento «%2» declara %3 entradas que no caben.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file has no vertex element.</source>
        <translation>No se puede leer «%1»: el archivo no tiene ningún elemento de vértices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: face %2 refers to vertex %3 but there are %4 vertices.</source>
        <translation>No se puede leer «%1»: la cara %2 se refiere al vértice %3, pero hay %4 vértices.</translation>
    </message>
    <message>
        <source>Cannot write the mesh: vertex %1 is not a finite point.</source>
        <translation>No se puede escribir la malla: el vértice %1 no es un punto finito.</translation>
    </message>
    <message>
        <source>Cannot write the mesh: face %1 refers to vertex %2 but there are only %3 vertices.</source>
        <translation>No se puede escribir la malla: la cara %1 se refiere al vértice %2, pero solo hay %3 vértices.</translation>
    </message>
    <message>
        <source>The mesh has a vertex with a non-finite coordinate.</source>
        <translation>La malla tiene un vértice con una coordenada no finita.</translation>
    </message>
    <message>
        <source>Face %1 refers to vertex %2 but the mesh has %3 vertices.</source>
        <translation>La cara %1 se refiere al vértice %2, pero la malla tiene %3 vértices.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: point %2 has %3 as its %4 coordinate; every coordinate must be a number.</source>
        <translation>Boceto «%1»: el punto %2 tiene %3 como coordenada %4; cada coordenada debe ser un número.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; is not valid JSON: %2</source>
        <translation>El boceto «%1» no es JSON válido: %2</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; has a number out of range: %2</source>
        <translation>El boceto «%1» tiene un número fuera de rango: %2</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; must be a JSON object with a &quot;points&quot; array of [x, y] pairs.</source>
        <translation>El boceto «%1» debe ser un objeto JSON con una matriz «points» de pares [x, y].</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; has no &quot;points&quot; array of [x, y] pairs.</source>
        <translation>El boceto «%1» no tiene ninguna matriz «points» de pares [x, y].</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: point %2 is not an [x, y] pair of numbers.</source>
        <translation>Boceto «%1»: el punto %2 no es un par de números [x, y].</translation>
    </message>
    <message>
        <source>Cannot read sketch &quot;%1&quot;: unknown file type &quot;%2&quot;; use a .json or .svg file.</source>
        <translation>No se puede leer el boceto «%1»: tipo de archivo desconocido «%2»; use un archivo .json o .svg.</translation>
    </message>
    <message>
        <source>Cannot read sketch file &quot;%1&quot;: it does not exist or is not readable.</source>
        <translation>No se puede leer el archivo de boceto «%1»: no existe o no se puede leer.</translation>
    </message>
    <message>
        <source>Cannot read sketch file &quot;%1&quot;: reading it failed.</source>
        <translation>No se puede leer el archivo de boceto «%1»: la lectura falló.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; is not valid SVG: %2</source>
        <translation>El boceto «%1» no es SVG válido: %2</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; is not an SVG document (no &lt;svg&gt; root element).</source>
        <translation>El boceto «%1» no es un documento SVG (no hay elemento raíz &lt;svg&gt;).</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; contains no path, polyline or polygon to use as the stroke.</source>
        <translation>El boceto «%1» no contiene ninguna ruta, polilínea ni polígono que usar como trazo.</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote invalid JSON</source>
        <translation>no se puede exportar: el exportador glTF escribió JSON no válido</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote an unknown component type</source>
        <translation>no se puede exportar: el exportador glTF escribió un tipo de componente desconocido</translation>
    </message>
    <message>
        <source>cannot export: a glTF accessor lies outside its buffer</source>
        <translation>no se puede exportar: un accessor glTF queda fuera de su búfer</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote a buffer view out of range</source>
        <translation>no se puede exportar: el exportador glTF escribió una vista de búfer fuera de rango</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote no buffer</source>
        <translation>no se puede exportar: el exportador glTF no escribió ningún búfer</translation>
    </message>
    <message>
        <source>cannot export: the COLLADA exporter wrote invalid XML</source>
        <translation>no se puede exportar: el exportador COLLADA escribió XML no válido</translation>
    </message>
    <message>
        <source>cannot export an animation of nothing</source>
        <translation>no se puede exportar una animación de nada</translation>
    </message>
    <message>
        <source>cannot export an animation without keys</source>
        <translation>no se puede exportar una animación sin claves</translation>
    </message>
    <message>
        <source>cannot export the animation: no node %1</source>
        <translation>no se puede exportar la animación: no hay ningún nodo %1</translation>
    </message>
    <message>
        <source>cannot export: the unit scale must be positive</source>
        <translation>no se puede exportar: la escala de unidades debe ser positiva</translation>
    </message>
    <message>
        <source>cannot export %1: unknown format &apos;%2&apos;; use .glb, .gltf, .fbx, .dae or .obj</source>
        <translation>no se puede exportar %1: formato desconocido «%2»; use .glb, .gltf, .fbx, .dae o .obj</translation>
    </message>
    <message>
        <source>part &apos;%1&apos; has no skeleton to export</source>
        <translation>la pieza «%1» no tiene esqueleto que exportar</translation>
    </message>
    <message>
        <source>cannot write the rig: vertex %1 is not at a finite position</source>
        <translation>no se puede escribir el rig: el vértice %1 no está en una posición finita</translation>
    </message>
    <message>
        <source>cannot write the rig: joint %1 is not at a finite position</source>
        <translation>no se puede escribir el rig: la articulación %1 no está en una posición finita</translation>
    </message>
    <message>
        <source>cannot write the rig: a weight of vertex %1 is not finite</source>
        <translation>no se puede escribir el rig: un peso del vértice %1 no es finito</translation>
    </message>
    <message>
        <source>there is no part at index %1 (the document has %2 part)</source>
        <translation>no hay ninguna pieza en el índice %1 (el documento tiene %2 pieza)</translation>
    </message>
    <message>
        <source>there is no part at index %1 (the document has %2 parts)</source>
        <translation>no hay ninguna pieza en el índice %1 (el documento tiene %2 piezas)</translation>
    </message>
    <message>
        <source>&quot;part&quot; must be a part&apos;s name or its index (from 0)</source>
        <translation>«part» debe ser el nombre de una pieza o su índice (desde 0)</translation>
    </message>
    <message>
        <source>there is no part &quot;%1&quot;</source>
        <translation>no hay ninguna pieza «%1»</translation>
    </message>
    <message>
        <source>%1 parts are named &quot;%2&quot;; refer to the part by its index</source>
        <translation>%1 piezas se llaman «%2»; refiérase a la pieza por su índice</translation>
    </message>
    <message>
        <source>part &quot;%1&quot; has no bone %2</source>
        <translation>la pieza «%1» no tiene el hueso %2</translation>
    </message>
    <message>
        <source>part &quot;%1&quot; has no joint %2</source>
        <translation>la pieza «%1» no tiene la articulación %2</translation>
    </message>
    <message>
        <source>part &quot;%1&quot; has no skeleton</source>
        <translation>la pieza «%1» no tiene esqueleto</translation>
    </message>
    <message>
        <source>&quot;mode&quot; must be &quot;add&quot;, &quot;subtract&quot;, &quot;replace&quot; or &quot;smooth&quot;</source>
        <translation>«mode» debe ser «add», «subtract», «replace» o «smooth»</translation>
    </message>
    <message>
        <source>&quot;falloff&quot; must be &quot;smooth&quot;, &quot;linear&quot;, &quot;sharp&quot; or &quot;constant&quot;</source>
        <translation>«falloff» debe ser «smooth», «linear», «sharp» o «constant»</translation>
    </message>
    <message>
        <source>&quot;locked&quot; must be a list of bone ids</source>
        <translation>«locked» debe ser una lista de identificadores de hueso</translation>
    </message>
    <message>
        <source>a dab needs &quot;center&quot; and &quot;radius&quot;</source>
        <translation>un toque necesita «center» y «radius»</translation>
    </message>
    <message>
        <source>the step needs &quot;center&quot; and &quot;radius&quot;</source>
        <translation>el paso necesita «center» y «radius»</translation>
    </message>
    <message>
        <source>the step needs either &quot;center&quot; and &quot;radius&quot; or &quot;dabs&quot;</source>
        <translation>el paso necesita o bien «center» y «radius» o bien «dabs»</translation>
    </message>
    <message>
        <source>&quot;dabs&quot; must be a non-empty list of {&quot;center&quot;, &quot;radius&quot;}</source>
        <translation>«dabs» debe ser una lista no vacía de {&quot;center&quot;, &quot;radius&quot;}</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a whole number from %2 to %3</source>
        <translation>«%1» debe ser un número entero de %2 a %3</translation>
    </message>
    <message>
        <source>the step needs &quot;%1&quot;</source>
        <translation>el paso necesita «%1»</translation>
    </message>
    <message>
        <source>the step needs either &quot;stroke&quot; (a sketch file) or &quot;points&quot;, not both</source>
        <translation>el paso necesita o bien «stroke» (un archivo de boceto) o bien «points», no ambos</translation>
    </message>
    <message>
        <source>the step needs either &quot;joint&quot; and &quot;target&quot; (an IK drag) or &quot;rotations&quot;</source>
        <translation>el paso necesita o bien «joint» y «target» (un arrastre IK) o bien «rotations»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; goes with &quot;rotations&quot;, not &quot;target&quot;</source>
        <translation>«%1» va con «rotations», no con «target»</translation>
    </message>
    <message>
        <source>&quot;reach&quot; must be &quot;limb&quot; or &quot;body&quot;</source>
        <translation>«reach» debe ser «limb» o «body»</translation>
    </message>
    <message>
        <source>&quot;reach&quot; goes with &quot;target&quot; (an IK drag), not &quot;rotations&quot;</source>
        <translation>«reach» va con «target» (un arrastre IK), no con «rotations»</translation>
    </message>
    <message>
        <source>&quot;interpolation&quot; must be &quot;constant&quot;, &quot;linear&quot; or &quot;smooth&quot;</source>
        <translation>«interpolation» debe ser «constant», «linear» o «smooth»</translation>
    </message>
    <message>
        <source>&quot;playback&quot; must be &quot;hold&quot;, &quot;loop&quot; or &quot;ping_pong&quot;</source>
        <translation>«playback» debe ser «hold», «loop» o «ping_pong»</translation>
    </message>
    <message>
        <source>&quot;times&quot; must be a list of seconds</source>
        <translation>«times» debe ser una lista de segundos</translation>
    </message>
    <message>
        <source>&quot;keys&quot; must be a list of keys</source>
        <translation>«keys» debe ser una lista de claves</translation>
    </message>
    <message>
        <source>each key needs &quot;time&quot; and &quot;rotations&quot;</source>
        <translation>cada clave necesita «time» y «rotations»</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a whole frame</source>
        <translation>«%1» debe ser un fotograma entero</translation>
    </message>
    <message>
        <source>&quot;mode&quot; must be &quot;snap&quot;, &quot;split&quot; or &quot;connect&quot;</source>
        <translation>«mode» debe ser «snap», «split» o «connect»</translation>
    </message>
    <message>
        <source>&quot;reskin&quot; must be &quot;local&quot; or &quot;global&quot;</source>
        <translation>«reskin» debe ser «local» o «global»</translation>
    </message>
    <message>
        <source>the step needs either &quot;plane&quot; or &quot;stroke&quot; with &quot;view&quot;</source>
        <translation>el paso necesita o bien «plane» o bien «stroke» con «view»</translation>
    </message>
    <message>
        <source>&quot;plane&quot; needs &quot;point&quot; and &quot;normal&quot;</source>
        <translation>«plane» necesita «point» y «normal»</translation>
    </message>
    <message>
        <source>&quot;view&quot; needs &quot;direction&quot; and &quot;up&quot;</source>
        <translation>«view» necesita «direction» y «up»</translation>
    </message>
    <message>
        <source>the cut needs a stroke of two points or more</source>
        <translation>el corte necesita un trazo de dos puntos o más</translation>
    </message>
    <message>
        <source>&quot;style&quot; must be &quot;smooth&quot; or &quot;sharp&quot;</source>
        <translation>«style» debe ser «smooth» o «sharp»</translation>
    </message>
    <message>
        <source>&quot;names&quot; must be two names</source>
        <translation>«names» debe contener dos nombres</translation>
    </message>
    <message>
        <source>&quot;parts&quot; must be a non-empty list of parts, without &quot;part&quot;</source>
        <translation>«parts» debe ser una lista no vacía de piezas, sin «part»</translation>
    </message>
    <message>
        <source>unknown command &quot;%1&quot;</source>
        <translation>orden desconocida «%1»</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot;</source>
        <translation>campo desconocido «%1»</translation>
    </message>
    <message>
        <source>this is not a RigMesh recipe (it needs &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>esto no es una receta de RigMesh (necesita &quot;format&quot;: &quot;%1&quot;)</translation>
    </message>
    <message>
        <source>the recipe has no valid &quot;version&quot;</source>
        <translation>la receta no tiene una «version» válida</translation>
    </message>
    <message>
        <source>the recipe is of version %1; this RigMesh Studio reads recipes of version %2 and older</source>
        <translation>la receta es de la versión %1; este RigMesh Studio lee recetas de la versión %2 y anteriores</translation>
    </message>
    <message>
        <source>the recipe has no list of &quot;steps&quot;</source>
        <translation>la receta no tiene ninguna lista «steps»</translation>
    </message>
    <message>
        <source>%1 is not valid JSON: %2</source>
        <translation>%1 no es JSON válido: %2</translation>
    </message>
    <message>
        <source>%1 has a number out of range: %2</source>
        <translation>%1 tiene un número fuera de rango: %2</translation>
    </message>
    <message>
        <source>cannot read the recipe %1</source>
        <translation>no se puede leer la receta %1</translation>
    </message>
    <message>
        <source>cannot write %1: the folder does not exist or is read-only</source>
        <translation>no se puede escribir %1: la carpeta no existe o es de solo lectura</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>no se puede escribir %1</translation>
    </message>
    <message>
        <source>&quot;edgeLength&quot; must be 0 (automatic) or a positive length</source>
        <translation>«edgeLength» debe ser 0 (automática) o una longitud positiva</translation>
    </message>
    <message>
        <source>&quot;points&quot; must be a list of [x, y] points</source>
        <translation>«points» debe ser una lista de puntos [x, y]</translation>
    </message>
    <message>
        <source>&quot;rotations&quot; must be an object {&quot;&lt;joint id&gt;&quot;: [w, x, y, z], ...}</source>
        <translation>«rotations» debe ser un objeto {&quot;&lt;joint id&gt;&quot;: [w, x, y, z], ...}</translation>
    </message>
    <message>
        <source>&quot;rotations&quot; names joint %1 twice</source>
        <translation>«rotations» nombra la articulación %1 dos veces</translation>
    </message>
    <message>
        <source>The surface of the part is not a manifold.</source>
        <translation>La superficie de la pieza no es una variedad.</translation>
    </message>
    <message>
        <source>The surface of the part has a hole, so it does not bound a volume.</source>
        <translation>La superficie de la pieza tiene un agujero, así que no encierra un volumen.</translation>
    </message>
    <message>
        <source>The surface of the cut is not a manifold.</source>
        <translation>La superficie del corte no es una variedad.</translation>
    </message>
    <message>
        <source>The surface of the target part is not a manifold.</source>
        <translation>La superficie de la pieza de destino no es una variedad.</translation>
    </message>
    <message>
        <source>The surface of the target part has a hole, so it does not bound a volume.</source>
        <translation>La superficie de la pieza de destino tiene un agujero, así que no encierra un volumen.</translation>
    </message>
    <message>
        <source>The surface of the dragged part is not a manifold.</source>
        <translation>La superficie de la pieza arrastrada no es una variedad.</translation>
    </message>
    <message>
        <source>The surface of the dragged part has a hole, so it does not bound a volume.</source>
        <translation>La superficie de la pieza arrastrada tiene un agujero, así que no encierra un volumen.</translation>
    </message>
    <message>
        <source>The surface of the mesh is not a manifold.</source>
        <translation>La superficie de la malla no es una variedad.</translation>
    </message>
    <message>
        <source>The surface of the mesh has a hole, so it does not bound a volume.</source>
        <translation>La superficie de la malla tiene un agujero, así que no encierra un volumen.</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: not a binary FBX file</source>
        <translation>no se puede reparar el archivo FBX: no es un archivo FBX binario</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: no node records</source>
        <translation>no se puede reparar el archivo FBX: no hay registros de nodo</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: a record runs past the end of the file</source>
        <translation>no se puede reparar el archivo FBX: un registro sobrepasa el final del archivo</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: a nested record is out of range</source>
        <translation>no se puede reparar el archivo FBX: un registro anidado está fuera de rango</translation>
    </message>
    <message>
        <source>cannot export: vertex %1 of mesh &apos;%2&apos; is not a finite number</source>
        <translation>no se puede exportar: el vértice %1 de la malla «%2» no es un número finito</translation>
    </message>
    <message>
        <source>cannot export: the normal of vertex %1 of mesh &apos;%2&apos; is not a finite number</source>
        <translation>no se puede exportar: la normal del vértice %1 de la malla «%2» no es un número finito</translation>
    </message>
    <message>
        <source>cannot export: the bind matrix of bone &apos;%1&apos; is not a finite number</source>
        <translation>no se puede exportar: la matriz de enlace del hueso «%1» no es un número finito</translation>
    </message>
    <message>
        <source>cannot export: a weight of bone &apos;%1&apos; is not a finite number</source>
        <translation>no se puede exportar: un peso del hueso «%1» no es un número finito</translation>
    </message>
    <message>
        <source>cannot export: the transform of node &apos;%1&apos; is not a finite number</source>
        <translation>no se puede exportar: la transformación del nodo «%1» no es un número finito</translation>
    </message>
    <message>
        <source>cannot export: a key of &apos;%1&apos; is not a finite number</source>
        <translation>no se puede exportar: una clave de «%1» no es un número finito</translation>
    </message>
    <message>
        <source>cannot export: the animation&apos;s duration is not a finite number</source>
        <translation>no se puede exportar: la duración de la animación no es un número finito</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the flow gave no curve.</source>
        <translation>No se pudo encontrar ningún esqueleto en la malla: el flujo no dio ninguna curva.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the curve is too short for a bone.</source>
        <translation>No se pudo encontrar ningún esqueleto en la malla: la curva es demasiado corta para un hueso.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the flow contracted it to a point.</source>
        <translation>No se pudo encontrar ningún esqueleto en la malla: el flujo la contrajo a un punto.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the mesh has too few vertices.</source>
        <translation>No se pudo encontrar ningún esqueleto en la malla: la malla tiene muy pocos vértices.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the mesh has no extent.</source>
        <translation>No se pudo encontrar ningún esqueleto en la malla: la malla no tiene extensión.</translation>
    </message>
    <message>
        <source>cannot write %1: the glTF exporter wrote no .bin</source>
        <translation>no se puede escribir %1: el exportador glTF no escribió ningún .bin</translation>
    </message>
    <message>
        <source>Skin weights could not be solved for bone %1; nearest-bone weights are used instead.</source>
        <translation>No se pudieron resolver los pesos de piel del hueso %1; se usan en su lugar los pesos del hueso más cercano.</translation>
    </message>
    <message>
        <source>Skin weights could not be solved for bones %1; nearest-bone weights are used instead.</source>
        <translation>No se pudieron resolver los pesos de piel de los huesos %1; se usan en su lugar los pesos del hueso más cercano.</translation>
    </message>
    <message>
        <source>The skin weights&apos; heat system could not be factored; every bone uses nearest-bone weights instead.</source>
        <translation>No se pudo factorizar el sistema de calor de los pesos de piel; cada hueso usa en su lugar los pesos del hueso más cercano.</translation>
    </message>
    <message>
        <source>%1 vertices see no bone from inside the shape and are heated by their nearest bone.</source>
        <translation>%1 vértices no ven ningún hueso desde dentro de la forma y los calienta su hueso más cercano.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected a letter in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: se esperaba una letra en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected a name in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: se esperaba un nombre en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected a number in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: se esperaba un número en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: number out of range in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: número fuera de rango en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected an arc flag (0 or 1) in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: se esperaba un indicador de arco (0 o 1) en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: path data must start with a moveto command (M or m) in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: los datos de ruta deben empezar con una orden moveto (M o m) en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: unknown command &apos;%5&apos; in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: orden desconocida «%5» en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: odd number of coordinates in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: número impar de coordenadas en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: unknown transform &apos;%5&apos; with %6 arguments in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: transformación desconocida «%5» con %6 argumentos en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected &apos;(&apos; after &apos;%5&apos; in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: se esperaba «(» después de «%5» en «%4»</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: missing &apos;)&apos; after &apos;%5&apos; in &quot;%4&quot;</source>
        <translation>Boceto «%1»: el atributo SVG «%2» está mal formado en el carácter %3: falta «)» después de «%5» en «%4»</translation>
    </message>
    <message>
        <source>%1 must be a list of %2 numbers</source>
        <translation>%1 debe ser una lista de %2 números</translation>
    </message>
    <message>
        <source>%1 must be a list of 4 numbers [w, x, y, z]</source>
        <translation>%1 debe ser una lista de 4 números [w, x, y, z]</translation>
    </message>
    <message>
        <source>%1 must be an object</source>
        <translation>%1 debe ser un objeto</translation>
    </message>
    <message>
        <source>%1 has an unknown field &quot;%2&quot;</source>
        <translation>%1 tiene un campo desconocido «%2»</translation>
    </message>
    <message>
        <source>%1 must be a number</source>
        <translation>%1 debe ser un número</translation>
    </message>
    <message>
        <source>%1 must be a finite number</source>
        <translation>%1 debe ser un número finito</translation>
    </message>
    <message>
        <source>%1 must be true or false</source>
        <translation>%1 debe ser true o false</translation>
    </message>
    <message>
        <source>%1 must be text</source>
        <translation>%1 debe ser texto</translation>
    </message>
    <message>
        <source>%1 is a zero quaternion</source>
        <translation>%1 es un cuaternión nulo</translation>
    </message>
    <message>
        <source>%1 is not a joint id</source>
        <translation>%1 no es un identificador de articulación</translation>
    </message>
    <message>
        <source>%1 must be a joint id (a non-negative integer)</source>
        <translation>%1 debe ser un identificador de articulación (un entero no negativo)</translation>
    </message>
    <message>
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>expected a map holding %1</source>
        <translation>se esperaba un mapa con %1</translation>
    </message>
    <message>
        <source>missing %1</source>
        <translation>falta %1</translation>
    </message>
    <message>
        <source>%1 is not a list</source>
        <translation>%1 no es una lista</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 no es un número</translation>
    </message>
    <message>
        <source>%1 holds a value that is not finite</source>
        <translation>%1 contiene un valor que no es finito</translation>
    </message>
    <message>
        <source>%1 is not true or false</source>
        <translation>%1 no es true ni false</translation>
    </message>
    <message>
        <source>%1 is not text</source>
        <translation>%1 no es texto</translation>
    </message>
    <message>
        <source>%1 has the wrong length</source>
        <translation>%1 tiene una longitud incorrecta</translation>
    </message>
    <message>
        <source>%1 is not an integer</source>
        <translation>%1 no es un número entero</translation>
    </message>
    <message>
        <source>%1 is out of range</source>
        <translation>%1 está fuera de rango</translation>
    </message>
    <message>
        <source>it ends too early, at byte %1</source>
        <translation>termina demasiado pronto, en el byte %1</translation>
    </message>
    <message>
        <source>it is malformed at byte %1</source>
        <translation>está mal formado en el byte %1</translation>
    </message>
    <message>
        <source>it holds a number too large to read</source>
        <translation>contiene un número demasiado grande para leerlo</translation>
    </message>
    <message>
        <source>a value has the wrong type</source>
        <translation>un valor tiene el tipo incorrecto</translation>
    </message>
    <message>
        <source>it is malformed</source>
        <translation>está mal formado</translation>
    </message>
    <message>
        <source>unknown weights warning %1</source>
        <translation>aviso de pesos desconocido %1</translation>
    </message>
    <message>
        <source>weights warning %1 has the wrong number of arguments</source>
        <translation>el aviso de pesos %1 tiene un número incorrecto de argumentos</translation>
    </message>
    <message>
        <source>%1 refers to a missing bone</source>
        <translation>%1 se refiere a un hueso que falta</translation>
    </message>
    <message>
        <source>%1 refers to bone %2, which the skeleton does not have</source>
        <translation>%1 se refiere al hueso %2, que el esqueleto no tiene</translation>
    </message>
    <message>
        <source>%1 does not have one entry per vertex</source>
        <translation>%1 no tiene una entrada por vértice</translation>
    </message>
    <message>
        <source>%1 has a malformed entry</source>
        <translation>%1 tiene una entrada mal formada</translation>
    </message>
    <message>
        <source>%1 holds a negative value</source>
        <translation>%1 contiene un valor negativo</translation>
    </message>
    <message>
        <source>the skin weights of vertex %1 sum to %2 instead of 1</source>
        <translation>los pesos de piel del vértice %1 suman %2 en lugar de 1</translation>
    </message>
    <message>
        <source>joint ids and positions differ in number</source>
        <translation>los id y las posiciones de las articulaciones no coinciden en número</translation>
    </message>
    <message>
        <source>duplicate or invalid joint id</source>
        <translation>id de articulación duplicado o no válido</translation>
    </message>
    <message>
        <source>bone ids, heads and tails differ in number</source>
        <translation>los id, cabezas y colas de los huesos no coinciden en número</translation>
    </message>
    <message>
        <source>duplicate bone id</source>
        <translation>id de hueso duplicado</translation>
    </message>
    <message>
        <source>a bone refers to a missing joint</source>
        <translation>un hueso se refiere a una articulación que falta</translation>
    </message>
    <message>
        <source>the skeleton root is not one of its joints</source>
        <translation>la raíz del esqueleto no es una de sus articulaciones</translation>
    </message>
    <message>
        <source>attached joints and their bones differ in number</source>
        <translation>las articulaciones unidas y sus huesos no coinciden en número</translation>
    </message>
    <message>
        <source>an attachment refers to a missing joint or bone, or twice to one joint</source>
        <translation>una unión se refiere a una articulación o un hueso que falta, o dos veces a una articulación</translation>
    </message>
    <message>
        <source>the skeleton is not a tree: %1</source>
        <translation>el esqueleto no es un árbol: %1</translation>
    </message>
    <message>
        <source>a face refers to a missing vertex</source>
        <translation>una cara se refiere a un vértice que falta</translation>
    </message>
    <message>
        <source>unknown vertex origin kind</source>
        <translation>tipo de origen de vértice desconocido</translation>
    </message>
    <message>
        <source>the mirror map refers to a missing vertex</source>
        <translation>el mapa de simetría se refiere a un vértice que falta</translation>
    </message>
    <message>
        <source>a rigged part needs skin weights for every vertex</source>
        <translation>una pieza con rig necesita pesos de piel para cada vértice</translation>
    </message>
    <message>
        <source>a bone name is not [bone id, name]</source>
        <translation>un nombre de hueso no es [id de hueso, nombre]</translation>
    </message>
    <message>
        <source>a bone name refers to a missing bone, or twice to one</source>
        <translation>un nombre de hueso se refiere a un hueso que falta, o dos veces a uno</translation>
    </message>
    <message>
        <source>a locked bone refers to a missing bone, or twice to one</source>
        <translation>un hueso bloqueado se refiere a un hueso que falta, o dos veces a uno</translation>
    </message>
    <message>
        <source>a bone frame is not [bone id, w, x, y, z]</source>
        <translation>un marco de hueso no es [id de hueso, w, x, y, z]</translation>
    </message>
    <message>
        <source>a bone frame is not a unit rotation of a bone, or names one twice</source>
        <translation>un marco de hueso no es una rotación unitaria de un hueso, o nombra uno dos veces</translation>
    </message>
    <message>
        <source>the part fails its own check: %1</source>
        <translation>la pieza no supera su propia comprobación: %1</translation>
    </message>
    <message>
        <source>step %1 (%2): %3</source>
        <translation>paso %1 (%2): %3</translation>
    </message>
    <message>
        <source>a step must be an object {&quot;command&quot;: ..., ...}</source>
        <translation>un paso debe ser un objeto {&quot;command&quot;: ..., ...}</translation>
    </message>
    <message>
        <source>the step has no &quot;command&quot;</source>
        <translation>el paso no tiene &quot;command&quot;</translation>
    </message>
    <message>
        <source>&quot;command&quot; must be text</source>
        <translation>&quot;command&quot; debe ser texto</translation>
    </message>
    <message>
        <source>Vertex %1 has a non-finite position.</source>
        <translation>El vértice %1 tiene una posición no finita.</translation>
    </message>
    <message>
        <source>Face %1 refers to a missing vertex.</source>
        <translation>La cara %1 se refiere a un vértice que falta.</translation>
    </message>
    <message>
        <source>Face %1 repeats a vertex.</source>
        <translation>La cara %1 repite un vértice.</translation>
    </message>
    <message>
        <source>The outline has a non-finite point.</source>
        <translation>El contorno tiene un punto no finito.</translation>
    </message>
    <message>
        <source>The vertex origins do not have one entry per vertex.</source>
        <translation>Los orígenes de los vértices no tienen una entrada por vértice.</translation>
    </message>
    <message>
        <source>The mirror map does not have one entry per vertex.</source>
        <translation>El mapa de simetría no tiene una entrada por vértice.</translation>
    </message>
    <message>
        <source>The mirror map refers to a missing vertex.</source>
        <translation>El mapa de simetría se refiere a un vértice que falta.</translation>
    </message>
    <message>
        <source>The skin weights do not have one entry per vertex.</source>
        <translation>Los pesos de piel no tienen una entrada por vértice.</translation>
    </message>
    <message>
        <source>The skin weights have %1 entries for %2 vertices.</source>
        <translation>Los pesos de piel tienen %1 entradas para %2 vértices.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 name bone %2, which the skeleton does not have.</source>
        <translation>Los pesos de piel del vértice %1 nombran el hueso %2, que el esqueleto no tiene.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 are not in bone order.</source>
        <translation>Los pesos de piel del vértice %1 no están en orden de huesos.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 hold a value that is not finite and positive.</source>
        <translation>Los pesos de piel del vértice %1 contienen un valor que no es finito y positivo.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 sum to %2, not 1.</source>
        <translation>Los pesos de piel del vértice %1 suman %2, no 1.</translation>
    </message>
    <message>
        <source>The known closest bones have %1 entries for %2 vertices.</source>
        <translation>Los huesos más cercanos conocidos tienen %1 entradas para %2 vértices.</translation>
    </message>
    <message>
        <source>The known closest bones of vertex %1 name bone %2, which the skeleton does not have.</source>
        <translation>Los huesos más cercanos conocidos del vértice %1 nombran el hueso %2, que el esqueleto no tiene.</translation>
    </message>
    <message>
        <source>The known closest bones of vertex %1 are not in bone order.</source>
        <translation>Los huesos más cercanos conocidos del vértice %1 no están en orden de huesos.</translation>
    </message>
    <message>
        <source>The known closest bones of vertex %1 hold a value that is not finite and positive.</source>
        <translation>Los huesos más cercanos conocidos del vértice %1 contienen un valor que no es finito y positivo.</translation>
    </message>
    <message>
        <source>The skeleton has bones but no joints.</source>
        <translation>El esqueleto tiene huesos pero ninguna articulación.</translation>
    </message>
    <message>
        <source>An unrigged part has skin weights.</source>
        <translation>Una pieza sin rig tiene pesos de piel.</translation>
    </message>
    <message>
        <source>The failed bones name a missing bone.</source>
        <translation>Los huesos fallidos nombran un hueso que falta.</translation>
    </message>
    <message>
        <source>A bone name is empty, repeated or names a missing bone.</source>
        <translation>Un nombre de hueso está vacío, repetido o nombra un hueso que falta.</translation>
    </message>
    <message>
        <source>Bone %1 is locked but the skeleton has no such bone.</source>
        <translation>El hueso %1 está bloqueado pero el esqueleto no tiene ese hueso.</translation>
    </message>
    <message>
        <source>A bone frame is not a unit rotation or names a missing bone.</source>
        <translation>Un marco de hueso no es una rotación unitaria o nombra un hueso que falta.</translation>
    </message>
    <message>
        <source>The mesh pieces do not fit the mesh.</source>
        <translation>Los trozos de malla no encajan en la malla.</translation>
    </message>
    <message>
        <source>Mesh piece &apos;%1&apos; uses another piece&apos;s vertex.</source>
        <translation>El trozo de malla «%1» usa un vértice de otro trozo.</translation>
    </message>
    <message>
        <source>The mesh pieces do not cover the mesh.</source>
        <translation>Los trozos de malla no cubren la malla.</translation>
    </message>
    <message>
        <source>The surface has %1 boundary edges.</source>
        <translation>La superficie tiene %1 aristas de borde.</translation>
    </message>
    <message>
        <source>The surface is not a manifold.</source>
        <translation>La superficie no es una variedad.</translation>
    </message>
    <message>
        <source>The surface is not consistently oriented.</source>
        <translation>La superficie no está orientada de forma coherente.</translation>
    </message>
    <message>
        <source>The skeleton has no joints.</source>
        <translation>El esqueleto no tiene articulaciones.</translation>
    </message>
    <message>
        <source>Two joints share the id %1.</source>
        <translation>Dos articulaciones comparten el id %1.</translation>
    </message>
    <message>
        <source>Joint %1 has a non-finite position.</source>
        <translation>La articulación %1 tiene una posición no finita.</translation>
    </message>
    <message>
        <source>Two bones share the id %1.</source>
        <translation>Dos huesos comparten el id %1.</translation>
    </message>
    <message>
        <source>The skeleton has no root joint.</source>
        <translation>El esqueleto no tiene articulación raíz.</translation>
    </message>
    <message>
        <source>The root is joint %1, which does not exist.</source>
        <translation>La raíz es la articulación %1, que no existe.</translation>
    </message>
    <message>
        <source>Bone %1 refers to joint %2, which does not exist.</source>
        <translation>El hueso %1 se refiere a la articulación %2, que no existe.</translation>
    </message>
    <message>
        <source>Bone %1 connects joint %2 to itself.</source>
        <translation>El hueso %1 une la articulación %2 consigo misma.</translation>
    </message>
    <message>
        <source>Bone %1 has zero length.</source>
        <translation>El hueso %1 tiene longitud cero.</translation>
    </message>
    <message>
        <source>The skeleton has a cycle: bone %1 closes a loop.</source>
        <translation>El esqueleto tiene un ciclo: el hueso %1 cierra un bucle.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from a bone but does not exist.</source>
        <translation>La articulación %1 cuelga de un hueso pero no existe.</translation>
    </message>
    <message>
        <source>The root joint %1 hangs from a bone.</source>
        <translation>La articulación raíz %1 cuelga de un hueso.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from bone %2, which does not exist.</source>
        <translation>La articulación %1 cuelga del hueso %2, que no existe.</translation>
    </message>
    <message>
        <source>Joints %1 and %2 both hang from bones but are in one chain.</source>
        <translation>Las articulaciones %1 y %2 cuelgan ambas de huesos pero están en una misma cadena.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from a bone but is connected to the root&apos;s chain.</source>
        <translation>La articulación %1 cuelga de un hueso pero está unida a la cadena de la raíz.</translation>
    </message>
    <message>
        <source>The skeleton is not connected: it has %1 separate components.</source>
        <translation>El esqueleto no es conexo: tiene %1 componentes separados.</translation>
    </message>
    <message>
        <source>The skeleton is not connected: it has %1 separate components, %2 of them hanging from no bone.</source>
        <translation>El esqueleto no es conexo: tiene %1 componentes separados, %2 de ellos sin colgar de ningún hueso.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from a bone of its own chain.</source>
        <translation>La articulación %1 cuelga de un hueso de su propia cadena.</translation>
    </message>
    <message>
        <source>The chain of joint %1 hangs from chains that hang from it.</source>
        <translation>La cadena de la articulación %1 cuelga de cadenas que cuelgan de ella.</translation>
    </message>
    <message>
        <source>%1 props held in a hand (a handle through the fist) rigged as the arm&apos;s chain on to their far end</source>
        <translation>%1 objetos sujetos en una mano (un mango a través del puño) riggeados como la cadena del brazo hasta su extremo</translation>
    </message>
    <message>
        <source>%1 pieces worn at a limb&apos;s end (horns on a helmet, a crest) ride on the limb&apos;s last bone</source>
        <translation>%1 piezas llevadas al final de una extremidad (cuernos en un casco, una cresta) siguen su último hueso</translation>
    </message>
</context>
<context>
    <name>ImportPartsCommand</name>
    <message>
        <source>Import %1</source>
        <translation>Importar %1</translation>
    </message>
</context>
<context>
    <name>KeyPoseCommand</name>
    <message>
        <source>Key %1 at %2 s</source>
        <translation>Clave de %1 en %2 s</translation>
    </message>
</context>
<context>
    <name>MergePartsCommand</name>
    <message>
        <source>Merge %1 into %2</source>
        <translation>Fusionar %1 en %2</translation>
    </message>
    <message>
        <source>merged in %1 ms: %2 vertices, %3 bones; %4 vertices and %5 bones re-skinned</source>
        <translation>fusionado en %1 ms: %2 vértices, %3 huesos; %4 vértices y %5 huesos con pesos recalculados</translation>
    </message>
    <message numerus="yes">
        <source>; %n bone(s) pruned</source>
        <translation>
            <numerusform>; %n hueso eliminado</numerusform>
            <numerusform>; %n huesos eliminados</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %1 lost the pose, pins and keys of %n pruned joint(s)</source>
        <translation>
            <numerusform>; %1 perdió la pose, las fijaciones y las claves de %n articulación eliminada</numerusform>
            <numerusform>; %1 perdió la pose, las fijaciones y las claves de %n articulaciones eliminadas</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MoveKeyCommand</name>
    <message>
        <source>Move key of %1 from %2 s to %3 s</source>
        <translation>Mover clave de %1 de %2 s a %3 s</translation>
    </message>
</context>
<context>
    <name>MoveKeysCommand</name>
    <message numerus="yes">
        <source>Move %n key(s) of %1 by %2 s</source>
        <translation>
            <numerusform>Mover %n clave de %1 en %2 s</numerusform>
            <numerusform>Mover %n claves de %1 en %2 s</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MovePartCommand</name>
    <message>
        <source>Move %1</source>
        <translation>Mover %1</translation>
    </message>
    <message>
        <source>Rotate %1</source>
        <translation>Rotar %1</translation>
    </message>
</context>
<context>
    <name>PaintWeightsCommand</name>
    <message>
        <source>Paint Weights of %1</source>
        <translation>Pintar pesos de %1</translation>
    </message>
</context>
<context>
    <name>PasteKeysCommand</name>
    <message numerus="yes">
        <source>Paste %n key(s) into %1</source>
        <translation>
            <numerusform>Pegar %n clave en %1</numerusform>
            <numerusform>Pegar %n claves en %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>the clip of &quot;%1&quot; is not exported: the current pose is the file&apos;s rest shape</source>
        <translation>el clip de «%1» no se exporta: la pose actual es la forma de reposo del archivo</translation>
    </message>
    <message>
        <source>the clip of &quot;%1&quot; is not exported: its current pose is the file&apos;s one key</source>
        <translation>el clip de «%1» no se exporta: su pose actual es la única clave del archivo</translation>
    </message>
    <message>
        <source>RigMesh documents (*.%1)</source>
        <translation>Documentos de RigMesh (*.%1)</translation>
    </message>
</context>
<context>
    <name>RebuildPartCommand</name>
    <message>
        <source>Rebuild %1</source>
        <translation>Reconstruir %1</translation>
    </message>
    <message numerus="yes">
        <source>the pose, pins and keys of %n joint(s) were dropped: the new skeleton has no joint there</source>
        <translation>
            <numerusform>se descartaron la pose, las fijaciones y las claves de %n articulación: el nuevo esqueleto no tiene ninguna allí</numerusform>
            <numerusform>se descartaron la pose, las fijaciones y las claves de %n articulaciones: el nuevo esqueleto no tiene ninguna allí</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RenamePartCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Renombrar %1 a %2</translation>
    </message>
</context>
<context>
    <name>ResetPoseCommand</name>
    <message>
        <source>Reset pose of %1</source>
        <translation>Restablecer pose de %1</translation>
    </message>
</context>
<context>
    <name>RigPartCommand</name>
    <message>
        <source>Rig %1</source>
        <translation>Riggear %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 rigged with %n bone(s)</source>
        <translation>
            <numerusform>%1 riggeada con %n hueso</numerusform>
            <numerusform>%1 riggeada con %n huesos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex(es) saw no bone from inside and follow the closest one</source>
        <translation>
            <numerusform>; %n vértice no veía ningún hueso desde dentro y sigue al más cercano</numerusform>
            <numerusform>; %n vértices no veían ningún hueso desde dentro y siguen al más cercano</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Rig %1 with %n more part(s)</source>
        <translation>
            <numerusform>Riggear %1 con %n pieza más</numerusform>
            <numerusform>Riggear %1 con %n piezas más</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 and %2 more parts rigged as one with %n bone(s)</source>
        <translation>
            <numerusform>%1 y %2 piezas más riggeadas como una con %n hueso</numerusform>
            <numerusform>%1 y %2 piezas más riggeadas como una con %n huesos</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetBoneLockCommand</name>
    <message>
        <source>Lock Weights of %1 in %2</source>
        <translation>Bloquear pesos de %1 en %2</translation>
    </message>
    <message>
        <source>Unlock Weights of %1 in %2</source>
        <translation>Desbloquear pesos de %1 en %2</translation>
    </message>
</context>
<context>
    <name>SetClipSettingsCommand</name>
    <message>
        <source>Set clip of %1</source>
        <translation>Ajustar clip de %1</translation>
    </message>
</context>
<context>
    <name>SetJointPinnedCommand</name>
    <message>
        <source>Pin %1</source>
        <translation>Fijar %1</translation>
    </message>
    <message>
        <source>Unpin %1</source>
        <translation>Soltar %1</translation>
    </message>
</context>
<context>
    <name>SetPartVisibleCommand</name>
    <message>
        <source>Show %1</source>
        <translation>Mostrar %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Ocultar %1</translation>
    </message>
</context>
<context>
    <name>SetPoseCommand</name>
    <message>
        <source>Pose %1</source>
        <translation>Posar %1</translation>
    </message>
</context>
<context>
    <name>SetTimelineCommand</name>
    <message>
        <source>Set the frame range to %1-%2 at %3 fps</source>
        <translation>Ajustar el rango de fotogramas a %1-%2 a %3 fps</translation>
    </message>
</context>
<context>
    <name>WeightCleanupCommand</name>
    <message>
        <source>Normalize All Weights of %1</source>
        <translation>Normalizar todos los pesos de %1</translation>
    </message>
    <message>
        <source>Clean Weights of %1</source>
        <translation>Limpiar pesos de %1</translation>
    </message>
    <message>
        <source>Limit Total Weights of %1</source>
        <translation>Limitar el total de pesos de %1</translation>
    </message>
    <message>
        <source>Smooth All Weights of %1</source>
        <translation>Suavizar todos los pesos de %1</translation>
    </message>
    <message>
        <source>Recompute Weights of %1</source>
        <translation>Recalcular los pesos de %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::Autosave</name>
    <message>
        <source>Cannot create the recovery folder &quot;%1&quot;.</source>
        <translation>No se puede crear la carpeta de recuperación «%1».</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Sin título</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::DocumentFile</name>
    <message>
        <source>This is not a RigMesh Studio document.</source>
        <translation>Esto no es un documento de RigMesh Studio.</translation>
    </message>
    <message>
        <source>This document was saved by a newer RigMesh Studio (format version %1); this version reads format version %2 and older. Please update RigMesh Studio.</source>
        <translation>Este documento se guardó con un RigMesh Studio más reciente (versión de formato %1); esta versión lee la versión de formato %2 y anteriores. Actualice RigMesh Studio.</translation>
    </message>
    <message>
        <source>The file is empty.</source>
        <translation>El archivo está vacío.</translation>
    </message>
    <message>
        <source>The document is corrupt or truncated (%1).</source>
        <translation>El documento está dañado o truncado (%1).</translation>
    </message>
    <message>
        <source>Cannot save &quot;%1&quot;: %2</source>
        <translation>No se puede guardar «%1»: %2</translation>
    </message>
    <message>
        <source>Cannot open &quot;%1&quot;: %2</source>
        <translation>No se puede abrir «%1»: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>a pose rotation of %1 is not [joint, w, x, y, z]</source>
        <translation>una rotación de pose de %1 no es [articulación, w, x, y, z]</translation>
    </message>
    <message>
        <source>pose joint %1 of %2 is not a joint of its skeleton</source>
        <translation>la articulación de pose %1 de %2 no es una articulación de su esqueleto</translation>
    </message>
    <message>
        <source>the pose rotation of joint %1 of %2 is not finite or is zero</source>
        <translation>la rotación de pose de la articulación %1 de %2 no es finita o es cero</translation>
    </message>
    <message>
        <source>the pose of %1 rotates joint %2 twice</source>
        <translation>la pose de %1 rota la articulación %2 dos veces</translation>
    </message>
    <message>
        <source>the pose root translation of %1 has the wrong length</source>
        <translation>la traslación de raíz de la pose de %1 tiene una longitud incorrecta</translation>
    </message>
    <message>
        <source>the pose root translation of %1 is not finite</source>
        <translation>la traslación de raíz de la pose de %1 no es finita</translation>
    </message>
    <message>
        <source>the clip frame rate of %1 is not positive</source>
        <translation>la velocidad de fotogramas del clip de %1 no es positiva</translation>
    </message>
    <message>
        <source>a key time of %1 is not finite</source>
        <translation>un tiempo de clave de %1 no es finito</translation>
    </message>
    <message>
        <source>the clip of %1 has two keys at one time</source>
        <translation>el clip de %1 tiene dos claves en el mismo tiempo</translation>
    </message>
    <message>
        <source>unknown clip interpolation &quot;%1&quot;</source>
        <translation>interpolación de clip desconocida «%1»</translation>
    </message>
    <message>
        <source>unknown clip playback &quot;%1&quot;</source>
        <translation>reproducción de clip desconocida «%1»</translation>
    </message>
    <message>
        <source>the timeline: %1</source>
        <translation>la línea de tiempo: %1</translation>
    </message>
    <message>
        <source>pinned joint %1 of %2 is not a joint of its skeleton</source>
        <translation>la articulación fijada %1 de %2 no es una articulación de su esqueleto</translation>
    </message>
    <message>
        <source>a joint of %1 is pinned twice</source>
        <translation>una articulación de %1 está fijada dos veces</translation>
    </message>
    <message>
        <source>a part has no id</source>
        <translation>una pieza no tiene id</translation>
    </message>
    <message>
        <source>a placement has the wrong length</source>
        <translation>una colocación tiene una longitud incorrecta</translation>
    </message>
    <message>
        <source>the placement rotation of part %1 is not a unit quaternion</source>
        <translation>la rotación de colocación de la pieza %1 no es un cuaternión unitario</translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation>pieza %1: %2</translation>
    </message>
    <message>
        <source>a part has no geometry</source>
        <translation>una pieza no tiene geometría</translation>
    </message>
    <message>
        <source>invalid format version</source>
        <translation>versión de formato no válida</translation>
    </message>
    <message>
        <source>two parts have the same id</source>
        <translation>dos piezas tienen el mismo id</translation>
    </message>
    <message>
        <source>the next part id is already in use</source>
        <translation>el siguiente id de pieza ya está en uso</translation>
    </message>
    <message>
        <source>The document is corrupt: %1.</source>
        <translation>El documento está dañado: %1.</translation>
    </message>
    <message>
        <source>part %1 (&quot;%2&quot;)</source>
        <translation>pieza %1 («%2»)</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::PartNode</name>
    <message>
        <source>Joint %1</source>
        <translation>Articulación %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::PoseChange</name>
    <message>
        <source>%1 and key</source>
        <translation>%1 e insertar clave</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::SceneItemModel</name>
    <message>
        <source>%1 vertices, %2 faces</source>
        <translation>%1 vértices, %2 caras</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>Esqueleto</translation>
    </message>
    <message>
        <source>Joint %1 (root)</source>
        <translation>Articulación %1 (raíz)</translation>
    </message>
    <message>
        <source>Joint %1</source>
        <translation>Articulación %1</translation>
    </message>
    <message numerus="yes">
        <source>, bone %1: %n vertices</source>
        <translation>
            <numerusform>, hueso %1: %n vértice</numerusform>
            <numerusform>, hueso %1: %n vértices</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (pinned)</source>
        <translation>%1 (fijada)</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>Información</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>1 joint</source>
        <translation>1 articulación</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 articulaciones</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 hueso</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 huesos</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::TimelineEdits</name>
    <message numerus="yes">
        <source>Paste %n key(s)</source>
        <translation>
            <numerusform>Pegar %n clave</numerusform>
            <numerusform>Pegar %n claves</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::model::TimelineItemModel</name>
    <message>
        <source>%1: key at frame %2 (%3 s)</source>
        <translation>%1: clave en el fotograma %2 (%3 s)</translation>
    </message>
    <message>
        <source>Frame %1: %2 s</source>
        <translation>Fotograma %1: %2 s</translation>
    </message>
</context>
<context>
    <name>rigmesh::studio</name>
    <message>
        <source>Example: %1</source>
        <translation>Ejemplo: %1</translation>
    </message>
    <message>
        <source>Sketch a silhouette, get a rigged part.</source>
        <translation>Dibuje una silueta y obtenga una pieza con rig.</translation>
    </message>
    <message>
        <source>Save a picture of the window to FILE after start-up and quit.</source>
        <translation>Guardar una imagen de la ventana en ARCHIVO tras el arranque y salir.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>ARCHIVO</translation>
    </message>
    <message>
        <source>RigMesh Studio</source>
        <translation>RigMesh Studio</translation>
    </message>
    <message>
        <source>Building the example</source>
        <translation>Creando el ejemplo</translation>
    </message>
    <message>
        <source>The example was not built: %1</source>
        <translation>No se ha creado el ejemplo: %1</translation>
    </message>
    <message>
        <source>files</source>
        <translation>archivos</translation>
    </message>
    <message>
        <source>RigMesh documents to open, or 3D files (glTF, FBX, OBJ, ...) to import</source>
        <translation>Documentos de RigMesh que abrir, o archivos 3D (glTF, FBX, OBJ, ...) que importar</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::BusyBar</name>
    <message>
        <source>Working</source>
        <translation>Trabajando</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::CommandLineFiles</name>
    <message>
        <source>Cannot open %1</source>
        <translation>No se puede abrir %1</translation>
    </message>
    <message>
        <source>%1 is not a file this user may read.</source>
        <translation>%1 no es un archivo que este usuario pueda leer.</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 no existe.</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::CutTool</name>
    <message>
        <source>Cut: drag a line across a part, from outside it to outside it; release cuts it in two with a smooth face, Shift + release with a flat one; Esc cancels</source>
        <translation>Cortar: trace una línea a través de una pieza, de fuera a fuera; al soltar se corta en dos con una cara suave, Mayús + soltar con una plana; Esc cancela</translation>
    </message>
    <message>
        <source>Nothing cut: the line does not cross a part</source>
        <translation>No se ha cortado nada: la línea no atraviesa ninguna pieza</translation>
    </message>
    <message>
        <source>Nothing cut: draw the line across the whole part, from outside it to outside it</source>
        <translation>No se ha cortado nada: trace la línea a través de toda la pieza, de fuera a fuera</translation>
    </message>
    <message>
        <source>%1 in %2 ms (%3)</source>
        <translation>%1 en %2 ms (%3)</translation>
    </message>
    <message>
        <source>smooth face</source>
        <translation>cara suave</translation>
    </message>
    <message>
        <source>flat face</source>
        <translation>cara plana</translation>
    </message>
    <message>
        <source>Nothing cut: %1</source>
        <translation>No se ha cortado nada: %1</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Cortar</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::DocumentView</name>
    <message>
        <source>Created %1</source>
        <translation>Se ha creado %1</translation>
    </message>
    <message>
        <source>Nothing created: %1</source>
        <translation>No se ha creado nada: %1</translation>
    </message>
    <message>
        <source>Part %1</source>
        <translation>Pieza %1</translation>
    </message>
    <message>
        <source>Building %1</source>
        <translation>Construyendo %1</translation>
    </message>
    <message>
        <source>Nothing created: the stroke crosses itself where the red cross is; draw a silhouette that does not cross itself</source>
        <translation>No se creó nada: el trazo se cruza a sí mismo donde está la cruz roja; dibuje una silueta que no se cruce</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ExchangeController</name>
    <message>
        <source>Import</source>
        <translation>Importar</translation>
    </message>
    <message>
        <source>3D scenes (*.glb *.gltf *.fbx *.dae *.obj *.ply *.off *.stl);;All files (*)</source>
        <translation>Escenas 3D (*.glb *.gltf *.fbx *.dae *.obj *.ply *.off *.stl);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importando %1</translation>
    </message>
    <message>
        <source>Cannot import</source>
        <translation>No se puede importar</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Importación de %1 cancelada</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n part(s) from %1</source>
        <translation>
            <numerusform>Se ha importado %n pieza de %1</numerusform>
            <numerusform>Se han importado %n piezas de %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>: %n of them without a skeleton, so they cannot be posed yet.</source>
        <translation>
            <numerusform>: %n de ellas sin esqueleto, así que aún no se puede posar.</numerusform>
            <numerusform>: %n de ellas sin esqueleto, así que aún no se pueden posar.</numerusform>
        </translation>
    </message>
    <message>
        <source>Save History as Recipe</source>
        <translation>Guardar historial como receta</translation>
    </message>
    <message>
        <source>RigMesh recipes (*.json)</source>
        <translation>Recetas de RigMesh (*.json)</translation>
    </message>
    <message>
        <source>Saved the history as %1: replay it with rigmesh run</source>
        <translation>Se ha guardado el historial como %1: reprodúzcalo con rigmesh run</translation>
    </message>
    <message>
        <source>Cannot save the recipe</source>
        <translation>No se puede guardar la receta</translation>
    </message>
    <message>
        <source>Nothing to export: sketch a part first</source>
        <translation>No hay nada que exportar: dibuje primero una pieza</translation>
    </message>
    <message>
        <source>Exporting %1</source>
        <translation>Exportando %1</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>No se puede exportar</translation>
    </message>
    <message>
        <source>%1 could not be replaced: %2</source>
        <translation>No se ha podido reemplazar %1: %2</translation>
    </message>
    <message>
        <source>no animation: no visible part has keys</source>
        <translation>sin animación: ninguna pieza visible tiene claves</translation>
    </message>
    <message>
        <source>Exported %1%2</source>
        <translation>Se ha exportado %1%2</translation>
    </message>
    <message>
        <source>Export of %1 cancelled: nothing written</source>
        <translation>Exportación de %1 cancelada: no se ha escrito nada</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ExportDialog</name>
    <message>
        <source>glTF 2.0 binary (.glb)</source>
        <translation>glTF 2.0 binario (.glb)</translation>
    </message>
    <message>
        <source>glTF 2.0 (.gltf + .bin)</source>
        <translation>glTF 2.0 (.gltf + .bin)</translation>
    </message>
    <message>
        <source>FBX binary (.fbx)</source>
        <translation>FBX binario (.fbx)</translation>
    </message>
    <message>
        <source>COLLADA (.dae)</source>
        <translation>COLLADA (.dae)</translation>
    </message>
    <message>
        <source>Wavefront OBJ, static mesh (.obj)</source>
        <translation>Wavefront OBJ, malla estática (.obj)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>all the format allows</source>
        <translation>todas las que permita el formato</translation>
    </message>
    <message>
        <source>Bones per vertex; extra influences are cut and the rest renormalised</source>
        <translation>Huesos por vértice; las influencias de más se eliminan y el resto se renormaliza</translation>
    </message>
    <message>
        <source>Rest pose</source>
        <translation>Posición de reposo</translation>
    </message>
    <message>
        <source>Current pose as the rest shape</source>
        <translation>Pose actual como forma de reposo</translation>
    </message>
    <message>
        <source>Current pose as one key</source>
        <translation>Pose actual como una clave</translation>
    </message>
    <message>
        <source>As one key, the file keeps the rest shape and the skeleton opens in the current pose (an animation of a single key at 0 s)</source>
        <translation>Como una clave, el archivo conserva la forma de reposo y el esqueleto se abre en la pose actual (una animación de una sola clave en 0 s)</translation>
    </message>
    <message>
        <source>Animation (each part&apos;s keyed clip)</source>
        <translation>Animación (el clip con claves de cada pieza)</translation>
    </message>
    <message>
        <source>Add leaf bones (an end bone at each leaf&apos;s tail)</source>
        <translation>Añadir huesos finales (un hueso final en la cola de cada hoja)</translation>
    </message>
    <message>
        <source>Like Blender&apos;s FBX option: importers then also know how long each leaf bone is (without, Blender gives a leaf its parent&apos;s length)</source>
        <translation>Como la opción FBX de Blender: así los importadores también saben cuánto mide cada hueso hoja (sin ellos, Blender da a un hueso hoja la longitud de su padre)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>Rounds of Loop subdivision: each makes four triangles of one; skin weights are carried</source>
        <translation>Pasadas de subdivisión Loop: cada una convierte un triángulo en cuatro; los pesos de piel se conservan</translation>
    </message>
    <message>
        <source>keep all</source>
        <translation>conservar todas</translation>
    </message>
    <message>
        <source> faces</source>
        <translation> caras</translation>
    </message>
    <message>
        <source>At most this many triangles per part (quadric error); every kept vertex keeps its weights</source>
        <translation>Como mucho esta cantidad de triángulos por pieza (error cuadrático); cada vértice conservado mantiene sus pesos</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Archivo</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Formato</translation>
    </message>
    <message>
        <source>Influences</source>
        <translation>Influencias</translation>
    </message>
    <message>
        <source>Subdivide</source>
        <translation>Subdividir</translation>
    </message>
    <message>
        <source>Decimate to</source>
        <translation>Diezmar a</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Pose</translation>
    </message>
    <message>
        <source>Export to</source>
        <translation>Exportar a</translation>
    </message>
    <message>
        <source>%1 (*.%2)</source>
        <translation>%1 (*.%2)</translation>
    </message>
    <message>
        <source>The file records dual quaternion skinning (Maya uses it); Blender skins it linearly unless Preserve Volume is on.</source>
        <translation>El archivo indica skinning con cuaterniones duales (Maya lo usa); Blender lo deforma por mezcla lineal salvo con «Preservar volumen».</translation>
    </message>
    <message>
        <source>The view bends with dual quaternions; this format is skinned linearly, so bent joints look different elsewhere.</source>
        <translation>La vista dobla con cuaterniones duales; este formato se deforma por mezcla lineal, así que las articulaciones dobladas se verán distintas en otros programas.</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::FilesController</name>
    <message>
        <source>Untitled %1</source>
        <translation>Sin título %1</translation>
    </message>
    <message>
        <source>Open Document</source>
        <translation>Abrir documento</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Se ha abierto %1</translation>
    </message>
    <message>
        <source>Cannot open document</source>
        <translation>No se puede abrir el documento</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Se ha guardado %1</translation>
    </message>
    <message>
        <source>Cannot save document</source>
        <translation>No se puede guardar el documento</translation>
    </message>
    <message>
        <source>Save Document</source>
        <translation>Guardar documento</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 tiene cambios sin guardar. ¿Guardarlos?</translation>
    </message>
    <message>
        <source>Recover unsaved work?</source>
        <translation>¿Recuperar el trabajo sin guardar?</translation>
    </message>
    <message>
        <source>Could not recover: %1</source>
        <translation>No se pudo recuperar: %1</translation>
    </message>
    <message>
        <source>RigMesh Studio did not close properly. Restore &quot;%1&quot;, autosaved %2?</source>
        <translation>RigMesh Studio no se cerró correctamente. ¿Restaurar «%1», guardado automáticamente el %2?</translation>
    </message>
    <message>
        <source>%1 (recovered)</source>
        <translation>%1 (recuperado)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::HistoryView</name>
    <message>
        <source>History</source>
        <translation>Historial</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::JobStatus</name>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Stop waiting: the document stays as it was (Esc)</source>
        <translation>Dejar de esperar: el documento queda como estaba (Esc)</translation>
    </message>
    <message>
        <source>%1… %2 s</source>
        <translation>%1… %2 s</translation>
    </message>
    <message>
        <source>%1… %2% (%3 s)</source>
        <translation>%1… %2 % (%3 s)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::KeyDrag</name>
    <message numerus="yes">
        <source>Move keys by %n frame(s)</source>
        <translation>
            <numerusform>Mover claves %n fotograma</numerusform>
            <numerusform>Mover claves %n fotogramas</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MainWindow</name>
    <message>
        <source>Ready: S sketches a part, Q selects, P poses; %1</source>
        <translation>Listo: S dibuja una pieza, Q selecciona, P posa; %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Principal</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Abrir...</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Guardar &amp;como...</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importar...</translation>
    </message>
    <message>
        <source>&amp;Export...</source>
        <translation>&amp;Exportar...</translation>
    </message>
    <message>
        <source>Save History as &amp;Recipe...</source>
        <translation>Guardar historial como &amp;receta...</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Cerrar</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>&amp;Delete Part</source>
        <translation>&amp;Eliminar pieza</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Preferencias...</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Vista</translation>
    </message>
    <message>
        <source>Frame &amp;All</source>
        <translation>Encuadrar &amp;todo</translation>
    </message>
    <message>
        <source>Frame &amp;Selected</source>
        <translation>Encuadrar &amp;selección</translation>
    </message>
    <message>
        <source>&amp;Wireframe</source>
        <translation>Estructura de &amp;alambre</translation>
    </message>
    <message>
        <source>&amp;Dual Quaternion Skinning</source>
        <translation>Skinning con &amp;cuaterniones duales</translation>
    </message>
    <message>
        <source>Off: linear blend skinning</source>
        <translation>Desactivado: skinning por mezcla lineal</translation>
    </message>
    <message>
        <source>Weights of the selected joint&apos;s bone: blue 0, green 0.5, red 1, dark blue none</source>
        <translation>Pesos del hueso de la articulación seleccionada: azul 0, verde 0,5, rojo 1, azul oscuro ninguno</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Cuadrícula</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <source>&amp;Select / Move</source>
        <translation>&amp;Seleccionar / Mover</translation>
    </message>
    <message>
        <source>S&amp;ketch Part</source>
        <translation>&amp;Dibujar pieza</translation>
    </message>
    <message>
        <source>&amp;Pose</source>
        <translation>&amp;Posar</translation>
    </message>
    <message>
        <source>&amp;Merge Parts</source>
        <translation>&amp;Fusionar piezas</translation>
    </message>
    <message>
        <source>&amp;Cut Part</source>
        <translation>&amp;Cortar pieza</translation>
    </message>
    <message>
        <source>Paint &amp;Weights</source>
        <translation>Pintar &amp;pesos</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>&amp;Mouse Gestures</source>
        <translation>&amp;Gestos del ratón</translation>
    </message>
    <message>
        <source>&amp;About RigMesh Studio</source>
        <translation>&amp;Acerca de RigMesh Studio</translation>
    </message>
    <message>
        <source>About RigMesh Studio</source>
        <translation>Acerca de RigMesh Studio</translation>
    </message>
    <message>
        <source>&lt;b&gt;RigMesh Studio&lt;/b&gt;&lt;p&gt;Sketch a silhouette, get a rigged part: surface, skeleton and skin weights, after Borosán et al., &lt;i&gt;RigMesh&lt;/i&gt;, SIGGRAPH Asia 2012.&lt;/p&gt;&lt;p&gt;GPL-3.0-or-later.&lt;/p&gt;</source>
        <translation>&lt;b&gt;RigMesh Studio&lt;/b&gt;&lt;p&gt;Dibuje una silueta y obtenga una pieza con rig: superficie, esqueleto y pesos de piel, según Borosán et al., &lt;i&gt;RigMesh&lt;/i&gt;, SIGGRAPH Asia 2012.&lt;/p&gt;&lt;p&gt;GPL-3.0-or-later.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Listado</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Propiedades</translation>
    </message>
    <message>
        <source>Skin Weights</source>
        <translation>Pesos de piel</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Historial</translation>
    </message>
    <message>
        <source>&lt;original&gt;</source>
        <translation>&lt;original&gt;</translation>
    </message>
    <message>
        <source>This tool has no options.</source>
        <translation>Esta herramienta no tiene opciones.</translation>
    </message>
    <message>
        <source>Tool Options</source>
        <translation>Opciones de herramienta</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>A&amp;nimación</translation>
    </message>
    <message>
        <source>&amp;Play / Pause</source>
        <translation>&amp;Reproducir / Pausa</translation>
    </message>
    <message>
        <source>Pre&amp;vious Frame</source>
        <translation>Fotograma a&amp;nterior</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>Fotograma &amp;siguiente</translation>
    </message>
    <message>
        <source>Jump to &amp;Start</source>
        <translation>Ir al &amp;inicio</translation>
    </message>
    <message>
        <source>Jump to &amp;End</source>
        <translation>Ir al &amp;final</translation>
    </message>
    <message>
        <source>&amp;Insert Key</source>
        <translation>Insertar &amp;clave</translation>
    </message>
    <message>
        <source>%1[*] - RigMesh Studio</source>
        <translation>%1[*] - RigMesh Studio</translation>
    </message>
    <message>
        <source>RigMesh Studio</source>
        <translation>RigMesh Studio</translation>
    </message>
    <message>
        <source>Select a part to delete</source>
        <translation>Seleccione la pieza que eliminar</translation>
    </message>
    <message>
        <source>The new language applies when RigMesh Studio starts again.</source>
        <translation>El nuevo idioma se aplicará cuando RigMesh Studio se vuelva a iniciar.</translation>
    </message>
    <message>
        <source>&amp;Auto-Rig Part</source>
        <translation>&amp;Rig automático de la pieza</translation>
    </message>
    <message>
        <source>Give the selected part without a skeleton (an imported mesh) a skeleton from its shape and skin weights</source>
        <translation>Dar a la pieza seleccionada sin esqueleto (una malla importada) un esqueleto a partir de su forma y pesos de piel</translation>
    </message>
    <message>
        <source>Co&amp;nnect Bone</source>
        <translation>Co&amp;nectar hueso</translation>
    </message>
    <message>
        <source>Move the selected bone&apos;s head onto its parent&apos;s tail, as Blender&apos;s Connected does (cut and merge need connected bones)</source>
        <translation>Mover la cabeza del hueso seleccionado a la cola de su padre, como «Conectado» de Blender (cortar y unir necesitan huesos conectados)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MergeTool</name>
    <message>
        <source>Drag the part into another to merge them</source>
        <translation>Arrastre la pieza dentro de otra para fusionarlas</translation>
    </message>
    <message>
        <source>%1 (%2 ms in all)</source>
        <translation>%1 (%2 ms en total)</translation>
    </message>
    <message>
        <source>Not merged: %1</source>
        <translation>No se ha fusionado: %1</translation>
    </message>
    <message>
        <source>Merge cancelled</source>
        <translation>Fusión cancelada</translation>
    </message>
    <message>
        <source>Merge</source>
        <translation>Fusionar</translation>
    </message>
    <message>
        <source>Merge: drag a part into another; release over the lit joints to snap, split or connect them (Shift + release splits, Ctrl + release connects at once); Esc cancels</source>
        <translation>Fusionar: arrastre una pieza dentro de otra; suelte sobre las articulaciones resaltadas para ajustarlas, dividir o conectarlas (Mayús + soltar divide, Ctrl + soltar conecta directamente); Esc cancela</translation>
    </message>
    <message>
        <source>Snap %1 of %2 onto %3 of %4 (Esc: cancel)</source>
        <translation>Ajustar %1 de %2 sobre %3 de %4 (Esc: cancelar)</translation>
    </message>
    <message>
        <source>Split a bone of %1 and snap %2 of %3 there (Esc: cancel)</source>
        <translation>Dividir un hueso de %1 y ajustar allí %2 de %3 (Esc: cancelar)</translation>
    </message>
    <message>
        <source>Connect %1 of %2 to %3 of %4 by a new bone (Esc: cancel)</source>
        <translation>Conectar %1 de %2 con %3 de %4 mediante un hueso nuevo (Esc: cancelar)</translation>
    </message>
    <message>
        <source>&amp;Snap the joints together</source>
        <translation>&amp;Ajustar las articulaciones</translation>
    </message>
    <message>
        <source>S&amp;plit the bone here</source>
        <translation>&amp;Dividir el hueso aquí</translation>
    </message>
    <message>
        <source>&amp;Connect by a new bone</source>
        <translation>&amp;Conectar con un hueso nuevo</translation>
    </message>
    <message>
        <source>Cancel (Esc)</source>
        <translation>Cancelar (Esc)</translation>
    </message>
    <message>
        <source>Merging %1 into %2</source>
        <translation>Fusionando %1 en %2</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MouseBindings</name>
    <message>
        <source>Alt + left drag orbits, Alt + middle drag pans, Alt + right drag or the wheel zooms</source>
        <translation>Alt + arrastre izquierdo orbita, Alt + arrastre central desplaza, Alt + arrastre derecho o la rueda hace zoom</translation>
    </message>
    <message>
        <source>middle drag orbits, Shift + middle drag pans, Ctrl + middle drag or the wheel zooms</source>
        <translation>arrastre central orbita, Mayús + arrastre central desplaza, Ctrl + arrastre central o la rueda hace zoom</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MouseHint</name>
    <message>
        <source>&lt;b&gt;Alt + left-drag&lt;/b&gt; orbits the view, &lt;b&gt;Alt + middle-drag&lt;/b&gt; pans, &lt;b&gt;Alt + right-drag&lt;/b&gt; zooms&lt;br&gt;</source>
        <translation>&lt;b&gt;Alt + arrastre izquierdo&lt;/b&gt; orbita la vista, &lt;b&gt;Alt + arrastre central&lt;/b&gt; la desplaza, &lt;b&gt;Alt + arrastre derecho&lt;/b&gt; hace zoom&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Middle-drag&lt;/b&gt; orbits the view, &lt;b&gt;Shift + middle-drag&lt;/b&gt; pans&lt;br&gt;</source>
        <translation>&lt;b&gt;Arrastre central&lt;/b&gt; orbita la vista, &lt;b&gt;Mayús + arrastre central&lt;/b&gt; la desplaza&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Left-drag&lt;/b&gt; draws a part with the Sketch tool (S), moves it with Select (Q), bends a joint or bone with Pose (P)&lt;br&gt;</source>
        <translation>&lt;b&gt;Arrastre izquierdo&lt;/b&gt; dibuja una pieza con la herramienta Boceto (S), la mueve con Seleccionar (Q) y dobla una articulación o un hueso con Posar (P)&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Wheel&lt;/b&gt; zooms, &lt;b&gt;Home&lt;/b&gt; frames everything&lt;br&gt;&lt;small&gt;Click to close; Help &amp;gt; Mouse Gestures shows this again&lt;/small&gt;</source>
        <translation>&lt;b&gt;Rueda&lt;/b&gt; hace zoom, &lt;b&gt;Inicio&lt;/b&gt; encuadra todo&lt;br&gt;&lt;small&gt;Haga clic para cerrar; Ayuda &amp;gt; Gestos del ratón lo vuelve a mostrar&lt;/small&gt;</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::OutlinerPanel</name>
    <message>
        <source>Outliner</source>
        <translation>Listado</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PaintTool</name>
    <message>
        <source>Paint Weights: select a joint (its bone is painted, shown red to blue), then drag over the part; Ctrl + click samples a vertex; Tool Options set the brush; Esc puts the stroke back</source>
        <translation>Pintar pesos: seleccione una articulación (se pinta su hueso, mostrado de rojo a azul) y arrastre sobre la pieza; Ctrl + clic toma una muestra de un vértice; las opciones de herramienta ajustan el pincel; Esc deshace el trazo</translation>
    </message>
    <message>
        <source>%1 is locked: unlock it in the Skin Weights panel to paint it</source>
        <translation>%1 está bloqueado: desbloquéelo en el panel Pesos de piel para pintarlo</translation>
    </message>
    <message>
        <source>Sampled %1 = %2 at vertex %3: the Replace brush paints it</source>
        <translation>Muestra %1 = %2 en el vértice %3: el pincel Reemplazar pinta ese valor</translation>
    </message>
    <message>
        <source>The stroke changed no weights: every other bone there is locked</source>
        <translation>El trazo no cambió ningún peso: todos los demás huesos allí están bloqueados</translation>
    </message>
    <message>
        <source>The stroke changed no weights: they are already as it paints</source>
        <translation>El trazo no cambió ningún peso: ya son como los pinta</translation>
    </message>
    <message numerus="yes">
        <source>Painted %n dab(s), %1 vertices changed</source>
        <translation>
            <numerusform>%n toque pintado, %1 vértices cambiados</numerusform>
            <numerusform>%n toques pintados, %1 vértices cambiados</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex visit(s) skipped: every other bone there is locked</source>
        <translation>
            <numerusform>; se omitió %n visita a vértices: todos los demás huesos allí están bloqueados</numerusform>
            <numerusform>; se omitieron %n visitas a vértices: todos los demás huesos allí están bloqueados</numerusform>
        </translation>
    </message>
    <message>
        <source>Stroke put back</source>
        <translation>Trazo deshecho</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
    <message>
        <source>Subtract</source>
        <translation>Restar</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Reemplazar</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Suavizar</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Pincel</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Sharp</source>
        <translation>Aguda</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Constante</translation>
    </message>
    <message>
        <source>How the brush&apos;s strength falls off from its centre to its rim</source>
        <translation>Cómo disminuye la fuerza del pincel desde el centro hasta el borde</translation>
    </message>
    <message>
        <source>Falloff</source>
        <translation>Caída</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radio</translation>
    </message>
    <message>
        <source>Strength</source>
        <translation>Fuerza</translation>
    </message>
    <message>
        <source>The weight the Replace brush paints towards (Ctrl + click samples)</source>
        <translation>El peso hacia el que pinta el pincel Reemplazar (Ctrl + clic toma una muestra)</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Peso</translation>
    </message>
    <message>
        <source>Front faces only</source>
        <translation>Solo caras frontales</translation>
    </message>
    <message>
        <source>Off: the brush also paints the far side of the part, through it</source>
        <translation>Desactivado: el pincel también pinta el lado opuesto de la pieza, a través de ella</translation>
    </message>
    <message>
        <source>Paint Weights</source>
        <translation>Pintar pesos</translation>
    </message>
    <message>
        <source>Select a joint first: its bone is the one painted</source>
        <translation>Seleccione primero una articulación: se pinta su hueso</translation>
    </message>
    <message>
        <source>The stroke did not pass over %1: nothing painted</source>
        <translation>El trazo no pasó por %1: no se pintó nada</translation>
    </message>
    <message>
        <source>The stroke changed no weights: %1 has one bone only, whose weight is 1 everywhere</source>
        <translation>El trazo no cambió ningún peso: %1 tiene un solo hueso, cuyo peso es 1 en todas partes</translation>
    </message>
    <message>
        <source>X-mirror (left and right)</source>
        <translation>Espejo en X (izquierda y derecha)</translation>
    </message>
    <message>
        <source>Also paints the other side, about the part&apos;s left-right mirror plane, on the bone&apos;s mirror image (Blender&apos;s X-mirror)</source>
        <translation>Pinta también el otro lado, respecto al plano de simetría izquierda-derecha de la pieza, en el hueso reflejado (el espejo en X de Blender)</translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex visit(s) painted on one side only: no mirror partner there</source>
        <translation>
            <numerusform>; %n visita a vértices pintada solo en un lado: allí no hay vértice simétrico</numerusform>
            <numerusform>; %n visitas a vértices pintadas solo en un lado: allí no hay vértice simétrico</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PoseController</name>
    <message>
        <source>&amp;Mirror Pose</source>
        <translation>&amp;Reflejar pose</translation>
    </message>
    <message>
        <source>&amp;Reset Pose</source>
        <translation>&amp;Restablecer pose</translation>
    </message>
    <message>
        <source>Select a part to reset its pose</source>
        <translation>Seleccione una pieza para restablecer su pose</translation>
    </message>
    <message>
        <source>Select a part to mirror its pose</source>
        <translation>Seleccione una pieza para reflejar su pose</translation>
    </message>
    <message>
        <source>%1 has no skeleton to pose</source>
        <translation>%1 no tiene esqueleto que posar</translation>
    </message>
    <message>
        <source>%1 has no left-right mirror plane: its two sides differ too much to mirror its pose</source>
        <translation>%1 no tiene plano de simetría izquierda-derecha: sus dos lados difieren demasiado para reflejar su pose</translation>
    </message>
    <message>
        <source>Mirror Pose of %1</source>
        <translation>Reflejar pose de %1</translation>
    </message>
    <message>
        <source>Mirrored the pose of %1 left to right</source>
        <translation>Pose de %1 reflejada de izquierda a derecha</translation>
    </message>
    <message>
        <source>Flip the selected part&apos;s pose left to right about its mirror plane, as Blender&apos;s Paste Pose Flipped</source>
        <translation>Refleja la pose de la pieza seleccionada de izquierda a derecha respecto a su plano de simetría, como «Pegar pose reflejada» de Blender</translation>
    </message>
    <message>
        <source>Put the selected part back in its rest pose</source>
        <translation>Devuelve la pieza seleccionada a su pose de reposo</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PoseTool</name>
    <message>
        <source>Pose: drag a joint (IK, this limb only); Alt + drag reaches through the whole body; drag a bone, Ctrl + drag the joint it ends at or drag the selected bone&apos;s ring to turn it (FK); Shift + click pins or unpins a joint</source>
        <translation>Posar: arrastre una articulación (IK, solo esta extremidad); Alt + arrastrar llega a todo el cuerpo; arrastre un hueso, con Ctrl la articulación en que termina o el anillo del hueso seleccionado para girarlo (FK); Mayús + clic fija o suelta una articulación</translation>
    </message>
    <message>
        <source>Click on a joint or a bone to pose the part</source>
        <translation>Haga clic en una articulación o un hueso para posar la pieza</translation>
    </message>
    <message>
        <source>The root joint ends no bone: drag its ring to turn the whole part, or drag it without Ctrl to move the part</source>
        <translation>En la articulación raíz no termina ningún hueso: arrastre su anillo para girar toda la pieza, o arrástrela sin Ctrl para mover la pieza</translation>
    </message>
    <message>
        <source>IK reaches through the whole body</source>
        <translation>La IK llega a todo el cuerpo</translation>
    </message>
    <message>
        <source>Off: a drag moves the limb up to the nearest junction or pinned joint. Alt + drag does the other for one drag.</source>
        <translation>Desactivado: arrastrar mueve la extremidad hasta la unión o articulación fijada más cercana. Alt + arrastrar hace lo contrario durante un arrastre.</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Posar</translation>
    </message>
    <message>
        <source>Not posed: %1</source>
        <translation>No se ha posado: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Preferencias</translation>
    </message>
    <message>
        <source>System default (%1)</source>
        <translation>Predeterminado del sistema (%1)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automática</translation>
    </message>
    <message>
        <source>The target edge length of each new sketch; Automatic takes the document&apos;s (its first sketched part&apos;s), or for the first part one from the sketch&apos;s size</source>
        <translation>La longitud de arista objetivo de cada boceto nuevo; Automática toma la del documento (la de su primera pieza dibujada) o, para la primera pieza, una según el tamaño del boceto</translation>
    </message>
    <message>
        <source>Dual quaternion</source>
        <translation>Cuaterniones duales</translation>
    </message>
    <message>
        <source>Linear blend</source>
        <translation>Mezcla lineal</translation>
    </message>
    <message>
        <source>How the view deforms posed parts (View &gt; Dual Quaternion Skinning)</source>
        <translation>Cómo deforma la vista las piezas posadas (Vista &gt; Skinning con cuaterniones duales)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Seconds from the last change until unsaved work is written to the recovery file</source>
        <translation>Segundos desde el último cambio hasta que el trabajo sin guardar se escribe en el archivo de recuperación</translation>
    </message>
    <message>
        <source>Blender</source>
        <translation>Blender</translation>
    </message>
    <message>
        <source>Maya</source>
        <translation>Maya</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Claro</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Oscuro</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Idioma:</translation>
    </message>
    <message>
        <source>Default &amp;edge length:</source>
        <translation>Longitud de &amp;arista predeterminada:</translation>
    </message>
    <message>
        <source>&amp;Skinning:</source>
        <translation>&amp;Skinning:</translation>
    </message>
    <message>
        <source>&amp;Autosave after:</source>
        <translation>&amp;Autoguardado tras:</translation>
    </message>
    <message>
        <source>&amp;Mouse bindings:</source>
        <translation>Asignación del &amp;ratón:</translation>
    </message>
    <message>
        <source>&amp;Theme:</source>
        <translation>&amp;Tema:</translation>
    </message>
    <message>
        <source>A new language applies when RigMesh Studio starts again.</source>
        <translation>Un idioma nuevo se aplica cuando RigMesh Studio se vuelve a iniciar.</translation>
    </message>
    <message>
        <source>Alt + drag is the view&apos;s, so the Pose tool reaches through the whole body with its Tool Options box</source>
        <translation>Alt + arrastrar es de la vista, así que la herramienta Posar llega a todo el cuerpo con la casilla de sus opciones de herramienta</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PropertiesPanel</name>
    <message>
        <source>Rebuild</source>
        <translation>Reconstruir</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automática</translation>
    </message>
    <message>
        <source>Target edge length of the surface; automatic = 1/60 of the sketch&apos;s size</source>
        <translation>Longitud de arista objetivo de la superficie; automática = 1/60 del tamaño del boceto</translation>
    </message>
    <message>
        <source>Least-squares smoothing</source>
        <translation>Suavizado por mínimos cuadrados</translation>
    </message>
    <message>
        <source>Edge length</source>
        <translation>Longitud de arista</translation>
    </message>
    <message>
        <source>Bone rotation (XYZ Euler)</source>
        <translation>Rotación del hueso (Euler XYZ)</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>The rotation from rest, in degrees, of the bone ending at the selected joint about its head, relative to its parent bone; at the root, of the whole part about the root</source>
        <translation>La rotación desde el reposo, en grados, del hueso que termina en la articulación seleccionada alrededor de su cabeza, relativa a su hueso padre; en la raíz, la de toda la pieza alrededor de la raíz</translation>
    </message>
    <message>
        <source>No part selected</source>
        <translation>Ninguna pieza seleccionada</translation>
    </message>
    <message>
        <source>Select a part in the viewport or the outliner.</source>
        <translation>Seleccione una pieza en la vista 3D o en el listado.</translation>
    </message>
    <message>
        <source>stroke of %1 points</source>
        <translation>trazo de %1 puntos</translation>
    </message>
    <message>
        <source>made by merging or importing: no stroke to rebuild from</source>
        <translation>creada por fusión o importación: no hay trazo desde el que reconstruir</translation>
    </message>
    <message>
        <source>Root joint %1: whole part (XYZ Euler)</source>
        <translation>Articulación raíz %1: toda la pieza (Euler XYZ)</translation>
    </message>
    <message>
        <source>Bone to joint %1 (XYZ Euler)</source>
        <translation>Hueso hasta la articulación %1 (Euler XYZ)</translation>
    </message>
    <message>
        <source>Not posed: %1</source>
        <translation>No se ha posado: %1</translation>
    </message>
    <message>
        <source>%1 has hand-painted skin weights. Rebuilding recomputes them from the sketch and the painting is lost (Undo brings it back). Rebuild anyway?</source>
        <translation>%1 tiene pesos de piel pintados a mano. Reconstruir los recalcula desde el boceto y se pierde lo pintado (Deshacer lo recupera). ¿Reconstruir de todos modos?</translation>
    </message>
    <message>
        <source>Not rebuilt: the painted weights are kept</source>
        <translation>No se ha reconstruido: se conservan los pesos pintados</translation>
    </message>
    <message>
        <source>Rebuilt %1</source>
        <translation>Se ha reconstruido %1</translation>
    </message>
    <message>
        <source>Rebuilt %1; %2</source>
        <translation>Se ha reconstruido %1; %2</translation>
    </message>
    <message>
        <source>Not rebuilt: %1</source>
        <translation>No se ha reconstruido: %1</translation>
    </message>
    <message>
        <source>Select a part to rebuild</source>
        <translation>Seleccione una pieza para reconstruirla</translation>
    </message>
    <message>
        <source>Rebuilding %1</source>
        <translation>Reconstruyendo %1</translation>
    </message>
    <message>
        <source>Rebuild of %1 cancelled</source>
        <translation>Reconstrucción de %1 cancelada</translation>
    </message>
    <message>
        <source>
Not rigged: imported as a static mesh. Tools &gt; Auto-Rig Part gives it a skeleton and skin weights.</source>
        <translation>
Sin rig: importada como malla estática. Herramientas &gt; Rig automático de la pieza le da un esqueleto y pesos de piel.</translation>
    </message>
    <message>
        <source>%1 vertices, %2 faces
%3, %4
</source>
        <translation>%1 vértices, %2 caras
%3, %4
</translation>
    </message>
    <message>
        <source>1 joint</source>
        <translation>1 articulación</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 articulaciones</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 hueso</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 huesos</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::RigController</name>
    <message>
        <source>Select a part to rig first</source>
        <translation>Selecciona primero una pieza para riggear</translation>
    </message>
    <message>
        <source>%1 already has a skeleton; Auto-Rig is for parts without one, such as imported meshes</source>
        <translation>%1 ya tiene un esqueleto; el rig automático es para piezas sin esqueleto, como las mallas importadas</translation>
    </message>
    <message>
        <source>Rigging %1</source>
        <translation>Riggeando %1</translation>
    </message>
    <message>
        <source>Cannot rig %1</source>
        <translation>No se puede riggear %1</translation>
    </message>
    <message>
        <source>Rigging %1 cancelled</source>
        <translation>Rigging de %1 cancelado</translation>
    </message>
    <message>
        <source>Imported without a rig</source>
        <translation>Importado sin rig</translation>
    </message>
    <message>
        <source>Rig Now</source>
        <translation>Riggear ahora</translation>
    </message>
    <message>
        <source>Not Now</source>
        <translation>Ahora no</translation>
    </message>
    <message>
        <source>Auto-Rig gives the imported meshes one skeleton from their shape and skin weights, so the figure can be posed, animated and painted like a sketched part. You can also do it later with Tools &gt; Auto-Rig Part.</source>
        <translation>El rig automático da a las mallas importadas un esqueleto a partir de su forma y pesos de piel, para que la figura se pueda posar, animar y pintar como una pieza dibujada. También puedes hacerlo más tarde con Herramientas &gt; Rig automático de la pieza.</translation>
    </message>
    <message>
        <source>Select the joint of the bone to connect first</source>
        <translation>Seleccione primero la articulación del hueso que quiere conectar</translation>
    </message>
    <message>
        <source>The selected joint ends no bone</source>
        <translation>En la articulación seleccionada no termina ningún hueso</translation>
    </message>
    <message>
        <source>Bone not connected: %1</source>
        <translation>Hueso no conectado: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::SelectTool</name>
    <message>
        <source>Select: click a part or a joint (with a weight view on, the click pins the vertex&apos;s weights in the Skin Weights panel); drag a part to move it, Ctrl + drag to turn it</source>
        <translation>Seleccionar: haga clic en una pieza o una articulación (con una vista de pesos activa, el clic fija los pesos del vértice en el panel Pesos de piel); arrastre una pieza para moverla, Ctrl + arrastrar la gira</translation>
    </message>
    <message>
        <source>Select</source>
        <translation>Seleccionar</translation>
    </message>
    <message>
        <source>%1 overlaps %2: moving does not join parts; the Merge tool (M) merges them</source>
        <translation>%1 se superpone a %2: mover no une piezas; la herramienta Fusionar (M) las fusiona</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ShortcutToolTips</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::SketchTool</name>
    <message>
        <source>Sketch: drag with the left button to draw a closed silhouette; release to inflate it into a rigged part</source>
        <translation>Boceto: arrastre con el botón izquierdo para dibujar una silueta cerrada; al soltar se infla hasta ser una pieza con rig</translation>
    </message>
    <message>
        <source>That stroke is too short: drag to draw a closed outline</source>
        <translation>Ese trazo es demasiado corto: arrastre para dibujar un contorno cerrado</translation>
    </message>
    <message>
        <source>Sketch</source>
        <translation>Boceto</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::TimelineDock</name>
    <message>
        <source>Jump to start (Shift+Left)</source>
        <translation>Ir al inicio (Mayús+Izquierda)</translation>
    </message>
    <message>
        <source>Previous frame (Left)</source>
        <translation>Fotograma anterior (Izquierda)</translation>
    </message>
    <message>
        <source>Play / pause (Space)</source>
        <translation>Reproducir / pausa (Espacio)</translation>
    </message>
    <message>
        <source>Next frame (Right)</source>
        <translation>Fotograma siguiente (Derecha)</translation>
    </message>
    <message>
        <source>Jump to end (Shift+Right)</source>
        <translation>Ir al final (Mayús+Derecha)</translation>
    </message>
    <message>
        <source>Current frame</source>
        <translation>Fotograma actual</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <source>First frame of the range</source>
        <translation>Primer fotograma del rango</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Fin</translation>
    </message>
    <message>
        <source>Last frame of the range</source>
        <translation>Último fotograma del rango</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Frame rate: keys stay on their frames when it changes</source>
        <translation>Velocidad de fotogramas: las claves se quedan en sus fotogramas cuando cambia</translation>
    </message>
    <message>
        <source>Clip</source>
        <translation>Clip</translation>
    </message>
    <message>
        <source>The clip the part keys and plays</source>
        <translation>El clip en el que la pieza inserta claves y que reproduce</translation>
    </message>
    <message>
        <source>New, duplicate, rename or delete clips</source>
        <translation>Crear, duplicar, renombrar o eliminar clips</translation>
    </message>
    <message>
        <source>Clip name:</source>
        <translation>Nombre del clip:</translation>
    </message>
    <message>
        <source>&amp;New Clip...</source>
        <translation>&amp;Nuevo clip...</translation>
    </message>
    <message>
        <source>New Clip</source>
        <translation>Nuevo clip</translation>
    </message>
    <message>
        <source>walk</source>
        <translation>caminar</translation>
    </message>
    <message>
        <source>&amp;Duplicate Clip...</source>
        <translation>&amp;Duplicar clip...</translation>
    </message>
    <message>
        <source>Duplicate Clip</source>
        <translation>Duplicar clip</translation>
    </message>
    <message>
        <source>&amp;Rename Clip...</source>
        <translation>&amp;Renombrar clip...</translation>
    </message>
    <message>
        <source>Rename Clip</source>
        <translation>Renombrar clip</translation>
    </message>
    <message>
        <source>D&amp;elete Clip</source>
        <translation>&amp;Eliminar clip</translation>
    </message>
    <message>
        <source>Interpolation between keys</source>
        <translation>Interpolación entre claves</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Constante</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Lineal</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Suave</translation>
    </message>
    <message>
        <source>Before the first and after the last key</source>
        <translation>Antes de la primera y después de la última clave</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Mantener</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Bucle</translation>
    </message>
    <message>
        <source>Ping-Pong</source>
        <translation>Ping-pong</translation>
    </message>
    <message>
        <source>● Auto Key</source>
        <translation>● Clave automática</translation>
    </message>
    <message>
        <source>Key every pose change at the current frame</source>
        <translation>Insertar una clave en el fotograma actual con cada cambio de pose</translation>
    </message>
    <message>
        <source>Onion Skin</source>
        <translation>Papel cebolla</translation>
    </message>
    <message>
        <source>Show the previous and next keyed poses as ghosts</source>
        <translation>Mostrar como fantasmas las poses con clave anterior y siguiente</translation>
    </message>
    <message>
        <source>Clip of %1</source>
        <translation>Clip de %1</translation>
    </message>
    <message>
        <source>Frame range not set: %1</source>
        <translation>No se ha ajustado el rango de fotogramas: %1</translation>
    </message>
    <message>
        <source>Clip not changed: %1</source>
        <translation>No se ha cambiado el clip: %1</translation>
    </message>
    <message>
        <source>No new clip: %1</source>
        <translation>No hay clip nuevo: %1</translation>
    </message>
    <message>
        <source>Not duplicated: %1</source>
        <translation>No se ha duplicado: %1</translation>
    </message>
    <message>
        <source>Not renamed: %1</source>
        <translation>No se ha renombrado: %1</translation>
    </message>
    <message>
        <source>Not deleted: %1</source>
        <translation>No se ha eliminado: %1</translation>
    </message>
    <message>
        <source>Clip not chosen: %1</source>
        <translation>No se ha elegido el clip: %1</translation>
    </message>
    <message>
        <source>Nothing to key: no part has a skeleton</source>
        <translation>Nada para la clave: ninguna pieza tiene esqueleto</translation>
    </message>
    <message numerus="yes">
        <source>Keyed %n part(s) at frame %1</source>
        <translation>
            <numerusform>Se ha insertado clave en %n pieza en el fotograma %1</numerusform>
            <numerusform>Se ha insertado clave en %n piezas en el fotograma %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Not keyed: %1</source>
        <translation>No se ha insertado clave: %1</translation>
    </message>
    <message>
        <source>Select keys to delete</source>
        <translation>Seleccione las claves que eliminar</translation>
    </message>
    <message numerus="yes">
        <source>Deleted %n key(s)</source>
        <translation>
            <numerusform>Se ha eliminado %n clave</numerusform>
            <numerusform>Se han eliminado %n claves</numerusform>
        </translation>
    </message>
    <message>
        <source>Select keys to copy</source>
        <translation>Seleccione las claves que copiar</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n key(s)</source>
        <translation>
            <numerusform>Se ha copiado %n clave</numerusform>
            <numerusform>Se han copiado %n claves</numerusform>
        </translation>
    </message>
    <message>
        <source>Copy keys first (Ctrl+C in the timeline)</source>
        <translation>Copie primero claves (Ctrl+C en la línea de tiempo)</translation>
    </message>
    <message>
        <source>Nothing pasted: the copied parts are gone</source>
        <translation>No se ha pegado nada: las piezas copiadas ya no existen</translation>
    </message>
    <message>
        <source>Pasted at frame %1</source>
        <translation>Pegado en el fotograma %1</translation>
    </message>
    <message>
        <source>Not pasted: %1</source>
        <translation>No se ha pegado: %1</translation>
    </message>
    <message>
        <source>Delete Keys</source>
        <translation>Eliminar claves</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::TimelineView</name>
    <message>
        <source>Frames</source>
        <translation>Fotogramas</translation>
    </message>
    <message>
        <source>Frame %1 = %2 s</source>
        <translation>Fotograma %1 = %2 s</translation>
    </message>
    <message>
        <source>Key at frame %1 (%2 s)</source>
        <translation>Clave en el fotograma %1 (%2 s)</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::UndoStatus</name>
    <message>
        <source>Undone: %1</source>
        <translation>Deshecho: %1</translation>
    </message>
    <message>
        <source>Redone: %1</source>
        <translation>Rehecho: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::UserAction</name>
    <message>
        <source>Internal error: %1</source>
        <translation>Error interno: %1</translation>
    </message>
    <message>
        <source>%1: internal error (%2)</source>
        <translation>%1: error interno (%2)</translation>
    </message>
    <message>
        <source>Out of memory.</source>
        <translation>Memoria insuficiente.</translation>
    </message>
    <message>
        <source>%1: out of memory</source>
        <translation>%1: memoria insuficiente</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::Viewpoint</name>
    <message>
        <source>&amp;Front</source>
        <translation>&amp;Frente</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Detrás</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>De&amp;recha</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>&amp;Izquierda</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>&amp;Arriba</translation>
    </message>
    <message>
        <source>B&amp;ottom</source>
        <translation>A&amp;bajo</translation>
    </message>
    <message>
        <source>View&amp;point</source>
        <translation>&amp;Punto de vista</translation>
    </message>
    <message>
        <source>&amp;Orthographic / Perspective</source>
        <translation>&amp;Ortográfica / Perspectiva</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::Viewport</name>
    <message>
        <source>Bone not changed: %1</source>
        <translation>No se ha cambiado el hueso: %1</translation>
    </message>
    <message>
        <source>Split Bone Here</source>
        <translation>Dividir hueso aquí</translation>
    </message>
    <message>
        <source>Delete Bone</source>
        <translation>Eliminar hueso</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL %1.%2 (core profile), which the &quot;%3&quot; display platform does not provide. Run RigMesh Studio on a desktop (X11 or Wayland) or under xvfb-run.</source>
        <translation>La vista 3D necesita OpenGL %1.%2 (perfil core), que la plataforma de pantalla «%3» no ofrece. Ejecute RigMesh Studio en un escritorio (X11 o Wayland) o con xvfb-run.</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL %1.%2, but the &quot;%3&quot; platform gives OpenGL %4.%5.</source>
        <translation>La vista 3D necesita OpenGL %1.%2, pero la plataforma «%3» ofrece OpenGL %4.%5.</translation>
    </message>
    <message>
        <source>OpenGL 3.3 shaders failed: %1</source>
        <translation>Fallaron los shaders de OpenGL 3.3: %1</translation>
    </message>
    <message>
        <source>Vertex %1 of %2: no weights</source>
        <translation>Vértice %1 de %2: sin pesos</translation>
    </message>
    <message>
        <source>bone %1 (to %2)</source>
        <translation>hueso %1 (hasta %2)</translation>
    </message>
    <message>
        <source>Vertex %1 of %2: %3</source>
        <translation>Vértice %1 de %2: %3</translation>
    </message>
    <message>
        <source>Point at a bone: K splits it there, Shift+K deletes it</source>
        <translation>Apunte a un hueso: K lo divide ahí, Mayús+K lo elimina</translation>
    </message>
    <message>
        <source>Connect Bone</source>
        <translation>Conectar hueso</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightViewChooser</name>
    <message>
        <source>&amp;Weights</source>
        <translation>&amp;Pesos</translation>
    </message>
    <message>
        <source>&amp;Off</source>
        <translation>&amp;Desactivado</translation>
    </message>
    <message>
        <source>&amp;Selected Bone (select its joint)</source>
        <translation>Hueso &amp;seleccionado (seleccione su articulación)</translation>
    </message>
    <message>
        <source>&amp;Dominant Bone</source>
        <translation>Hueso &amp;dominante</translation>
    </message>
    <message>
        <source>&amp;Influence Count</source>
        <translation>Número de &amp;influencias</translation>
    </message>
    <message>
        <source>Difference from &amp;Global Weights</source>
        <translation>Diferencia con los pesos &amp;globales</translation>
    </message>
    <message>
        <source>Weight View</source>
        <translation>Vista de pesos</translation>
    </message>
    <message>
        <source> Weights: </source>
        <translation> Pesos: </translation>
    </message>
    <message>
        <source>Colour the surface by its skin weights (View &gt; Weights)</source>
        <translation>Colorear la superficie según sus pesos de piel (Vista &gt; Pesos)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightsController</name>
    <message>
        <source>Recompute Weights</source>
        <translation>Recalcular pesos</translation>
    </message>
    <message>
        <source>Weigh&amp;ts</source>
        <translation>Pe&amp;sos</translation>
    </message>
    <message>
        <source>Select a part first</source>
        <translation>Seleccione primero una pieza</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n vertices changed</source>
        <translation>
            <numerusform>%1: %n vértice cambiado</numerusform>
            <numerusform>%1: %n vértices cambiados</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Normalize All</source>
        <translation>&amp;Normalizar todo</translation>
    </message>
    <message>
        <source>&amp;Clean (below 0.01)</source>
        <translation>&amp;Limpiar (por debajo de 0,01)</translation>
    </message>
    <message>
        <source>&amp;Limit Total (4 bones)</source>
        <translation>Limitar &amp;total (4 huesos)</translation>
    </message>
    <message>
        <source>&amp;Smooth All</source>
        <translation>&amp;Suavizar todo</translation>
    </message>
    <message>
        <source>Every unlocked bone&apos;s weight halfway towards its neighbours&apos; mean</source>
        <translation>El peso de cada hueso no bloqueado, a medio camino hacia la media de sus vecinos</translation>
    </message>
    <message>
        <source>&amp;Recompute Weights (Bone Heat)</source>
        <translation>&amp;Recalcular pesos (calor de huesos)</translation>
    </message>
    <message>
        <source>Bone heat over the whole part again, as a new sketch gets it; locked bones keep their weights</source>
        <translation>Calor de huesos de nuevo sobre toda la pieza, como lo recibe un boceto nuevo; los huesos bloqueados conservan sus pesos</translation>
    </message>
    <message>
        <source>Check &amp;Rig</source>
        <translation>&amp;Comprobar rig</translation>
    </message>
    <message>
        <source>%1 has no skeleton, so it has no weights to recompute</source>
        <translation>%1 no tiene esqueleto, así que no tiene pesos que recalcular</translation>
    </message>
    <message>
        <source>The weights of %1 were painted or cleaned up by hand. Recomputing them by bone heat replaces that work (locked bones keep theirs; Undo brings it back). Recompute anyway?</source>
        <translation>Los pesos de %1 se pintaron o limpiaron a mano. Recalcularlos con calor de huesos sustituye ese trabajo (los huesos bloqueados conservan los suyos; Deshacer lo recupera). ¿Recalcular de todos modos?</translation>
    </message>
    <message>
        <source>Weights not recomputed: the painted weights are kept</source>
        <translation>No se han recalculado los pesos: se conservan los pesos pintados</translation>
    </message>
    <message>
        <source>Recomputing the weights of %1</source>
        <translation>Recalculando los pesos de %1</translation>
    </message>
    <message>
        <source>Weights not recomputed: %1</source>
        <translation>No se han recalculado los pesos: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightsPanel</name>
    <message>
        <source>Bone</source>
        <translation>Hueso</translation>
    </message>
    <message>
        <source>Leads</source>
        <translation>Domina</translation>
    </message>
    <message>
        <source>Lock</source>
        <translation>Bloqueo</translation>
    </message>
    <message>
        <source>Leads: the vertices whose largest weight is the bone&apos;s. Lock: painting and the clean-ups keep the bone&apos;s weights. Click a bone to paint or view it.</source>
        <translation>Domina: los vértices cuyo mayor peso es el del hueso. Bloqueo: pintar y las limpiezas conservan los pesos del hueso. Haga clic en un hueso para pintarlo o verlo.</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Vértice</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Peso</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Bloqueado</translation>
    </message>
    <message>
        <source>Check Rig</source>
        <translation>Comprobar rig</translation>
    </message>
    <message>
        <source>at most </source>
        <translation>como máximo </translation>
    </message>
    <message>
        <source> bones</source>
        <translation> huesos</translation>
    </message>
    <message>
        <source>Vertices weighted by more bones are listed (glTF takes 4)</source>
        <translation>Se listan los vértices con pesos de más huesos (glTF admite 4)</translation>
    </message>
    <message>
        <source>%1 has no skeleton</source>
        <translation>%1 no tiene esqueleto</translation>
    </message>
    <message>
        <source>Select a part to see its bones&apos; weights</source>
        <translation>Seleccione una pieza para ver los pesos de sus huesos</translation>
    </message>
    <message>
        <source>Click a vertex with a weight view on (or Ctrl + click while painting) to pin its weights here.</source>
        <translation>Haga clic en un vértice con una vista de pesos activa (o Ctrl + clic al pintar) para fijar aquí sus pesos.</translation>
    </message>
    <message numerus="yes">
        <source>Vertex %1 of %2: %n bone(s), sum %3</source>
        <translation>
            <numerusform>Vértice %1 de %2: %n hueso, suma %3</numerusform>
            <numerusform>Vértice %1 de %2: %n huesos, suma %3</numerusform>
        </translation>
    </message>
    <message>
        <source>locked</source>
        <translation>bloqueado</translation>
    </message>
    <message>
        <source>Select a part to check its rig</source>
        <translation>Seleccione una pieza para comprobar su rig</translation>
    </message>
    <message>
        <source>Vertex %1</source>
        <translation>Vértice %1</translation>
    </message>
    <message>
        <source>... and %1 more (all marked when the group is clicked)</source>
        <translation>... y %1 más (todos marcados al hacer clic en el grupo)</translation>
    </message>
    <message>
        <source>Unweighted vertices: %1</source>
        <translation>Vértices sin peso: %1</translation>
    </message>
    <message>
        <source>Bones leading no vertex: %1</source>
        <translation>Huesos que no dominan ningún vértice: %1</translation>
    </message>
    <message>
        <source>Vertices over %1 influences: %2</source>
        <translation>Vértices con más de %1 influencias: %2</translation>
    </message>
    <message>
        <source>Vertices whose weights do not sum to 1: %1</source>
        <translation>Vértices cuyos pesos no suman 1: %1</translation>
    </message>
    <message>
        <source>Check Rig: %1 is clean</source>
        <translation>Comprobar rig: %1 está bien</translation>
    </message>
    <message>
        <source>Check Rig found problems in %1: click a line to select them</source>
        <translation>Comprobar rig encontró problemas en %1: haga clic en una línea para seleccionarlos</translation>
    </message>
    <message>
        <source>%1: %2, %3 locked</source>
        <translation>%1: %2, %3 bloqueados</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 hueso</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 huesos</translation>
    </message>
</context>
</TS>
